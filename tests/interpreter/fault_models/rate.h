// The header with_header.vvp includes; tests copy both and edit this one.
const int rate = 1;

// Where `vvc -o FILE` puts the C++, and what it never writes over.
//
//  * A regular file (or a name not taken yet) is replaced atomically: the
//    text goes into a temporary of a unique name in the same folder, which
//    is then renamed over it. Two runs writing one path never share a
//    temporary, and a failed write leaves the old file as it was.
//  * Through a symbolic link the file it names is written; the link stays.
//    A dangling link creates the file it names; a loop of links is refused.
//  * A character device or a FIFO (/dev/null, /dev/stdout, a named pipe) is
//    written through, as a shell redirection would: it is never replaced by
//    a regular file, and a failed write (/dev/full) is an error.
//  * Anything else (a folder, a block device, a socket) is refused.
#pragma once

#include <string>
#include <vector>

namespace vvc {

struct output_file {
  enum kind_t {
    replace,  // a regular file, or none yet: written atomically
    stream,   // a character device or FIFO: written through
    refused,  // not written; `why` says why
  };
  std::string target;  // the path written: `path` with its links followed
  kind_t kind = refused;
  std::string why;
};

//! What writing `path` would do.
output_file plan_output(const std::string& path);

//! Writes text as planned; "" or the system's reason ("No space left on
//! device").
std::string write_output(const output_file& out, const std::string& text);

//! After a failed translation: removes what an earlier run wrote, so that
//! it cannot pass for this one's output. Only a regular file (the one a
//! link names; the link stays); never a device or a pipe.
void remove_stale_output(const output_file& out);

//! Whether the two paths name one existing file (the same device and
//! inode, however spelt: "./a.vvp", a link, a hard link).
bool same_file(const std::string& a, const std::string& b);

//! The first of `sources` that `path` names, or "".
std::string source_at(const std::string& path, const std::vector<std::string>& sources);

}  // namespace vvc

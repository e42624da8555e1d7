// VV_INLINE marks the small functions of the algebra's hot paths (handle
// views, neighbour search, the queries and edits a subdivision step makes
// per edge). The interpreter compiles models at -O1, where GCC does not
// inline small non-member templates by itself; each would otherwise cost a
// call, and its arguments (the `where` of the caller) stores and loads.
#pragma once

#if defined(__GNUC__)
#define VV_INLINE inline __attribute__((always_inline))
#else
#define VV_INLINE inline
#endif

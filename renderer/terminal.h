#pragma once

#include <cstdio>

namespace raystep {

/// True when the stream is an interactive terminal (not a file, pipe or CI log), on POSIX and
/// Windows alike.
bool is_terminal(std::FILE* stream);

}  // namespace raystep

// What a caught exception says, in words for the user.
#pragma once

#include <exception>
#include <string>

namespace rs {

/// "out of memory" for std::bad_alloc, what() for any other std::exception, "unknown error"
/// for anything else thrown. Threads that must not let an exception escape (workers, the
/// designer's jobs) and the command line's last catch report failures with it.
std::string describeFailure(std::exception_ptr failure);

}  // namespace rs

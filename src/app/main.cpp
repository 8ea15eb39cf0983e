#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "app/commands.hpp"

namespace {

// Standard output is written through a buffer: a full disk or a closed pipe
// shows only when it is flushed and closed, so both are checked, and a
// failure is exit status 1 with a message (a walk cut short on a full disk
// must not look like success). A descriptor that was closed before the
// program started (`>&-`) and never written to is no failure.
int close_standard_output(int status) {
    errno = 0;
    std::cout.flush();  // through to stdout's buffer and on to the descriptor
    bool failed = !std::cout;
    int error = errno;
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        failed = true;
        if (errno) error = errno;
    }
    if (std::fclose(stdout) != 0 && !(errno == EBADF && !failed)) {
        if (!failed) error = errno;
        failed = true;
    }
    if (!failed) return status;
    std::cerr << "impossible: cannot write to standard output: " << (error ? std::strerror(error) : "write error")
              << "\n";
    return status == 0 ? 1 : status;
}

}  // namespace

int main(int argc, char** argv) {
    const int status = impossible::app::run_main(impossible::app::Args(argv + 1, argv + argc), std::cout, std::cerr);
    return close_standard_output(status);
}

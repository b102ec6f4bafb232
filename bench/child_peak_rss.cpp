// child_peak_rss RESULT_FILE COMMAND [ARGS...]: runs COMMAND and writes its peak resident set size in KiB (wait4's
// ru_maxrss) to RESULT_FILE; exits with COMMAND's exit status (128 + the signal that ended it).
//
// Why a launcher: Linux carries a process's peak RSS across exec(), so a child forked by a large process (a Python
// script holding a generated job) reports at least its parent's size. Forked from this small program, the command
// reports its own peak (above this program's few hundred KiB).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: child_peak_rss RESULT_FILE COMMAND [ARGS...]\n");
        return 2;
    }
    const pid_t pid = fork();
    if (pid < 0) {
        std::fprintf(stderr, "child_peak_rss: fork: %s\n", std::strerror(errno));
        return 2;
    }
    if (pid == 0) {
        execvp(argv[2], argv + 2);
        std::fprintf(stderr, "child_peak_rss: cannot run %s: %s\n", argv[2], std::strerror(errno));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0) {
        if (errno != EINTR) {
            std::fprintf(stderr, "child_peak_rss: wait4: %s\n", std::strerror(errno));
            return 2;
        }
    }
    std::FILE* out = std::fopen(argv[1], "w");
    if (out == nullptr || std::fprintf(out, "%ld\n", usage.ru_maxrss) < 0 || std::fclose(out) != 0) {
        std::fprintf(stderr, "child_peak_rss: cannot write %s\n", argv[1]);
        return 2;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

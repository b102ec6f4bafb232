#include "compare/spawn.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace cnc::sim {

pid_t spawn_child(const std::vector<std::string>& args, const std::string& cwd, const std::string& stderr_path,
                  const std::string& stdout_path) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (stdout_path.empty())
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    else
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                         0644);
    if (!stderr_path.empty())
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                         0644);
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
    pid_t pid = 0;
    const int err = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (err != 0) throw std::runtime_error(std::string("cannot start ") + argv[0] + ": " + std::strerror(err));
    return pid;
}

pid_t wait_any_child(int& exit_code) {
    int wstatus = 0;
    pid_t pid = 0;
    while ((pid = waitpid(-1, &wstatus, 0)) < 0) {
        if (errno != EINTR) throw std::runtime_error("waitpid failed");
    }
    exit_code = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 1;
    return pid;
}

int run_child(const std::vector<std::string>& args, const std::string& cwd, const std::string& stdout_path) {
    const pid_t pid = spawn_child(args, cwd, "", stdout_path);
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0) {
        if (errno != EINTR) throw std::runtime_error("waitpid failed");
    }
    return WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 1;
}

}  // namespace cnc::sim

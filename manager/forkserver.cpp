// SPDX-License-Identifier: MIT
// Requests are a 32-bit length and the arguments, each ended by a NUL byte; the answer is the new
// process's id as a 32-bit number (-1 when fork failed). Both ends use native byte order: they are
// the same program on the same host.
#include "forkserver.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace Runtime {

std::string ownExecutable()
{
    static const std::string self = "/proc/self/exe";
    char buffer[4096];
    const ssize_t length = ::readlink(self.c_str(), buffer, sizeof buffer - 1);
    if (length <= 0)
        return self;
    const std::string path(buffer, size_t(length));
    struct stat running {}, named {};
    if (::stat(self.c_str(), &running) != 0 || ::stat(path.c_str(), &named) != 0
        || running.st_dev != named.st_dev || running.st_ino != named.st_ino)
        return self; // replaced or removed since it started
    return path;
}

namespace {

/// Requests longer than this are refused: an argument list of a manager is a few KiB.
constexpr std::uint32_t MaxRequest = 1024 * 1024;

bool writeAll(int fd, const void *data, size_t size)
{
    const char *p = static_cast<const char *>(data);
    while (size > 0) {
        const ssize_t n = ::send(fd, p, size, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        p += n;
        size -= size_t(n);
    }
    return true;
}

bool readAll(int fd, void *data, size_t size)
{
    char *p = static_cast<char *>(data);
    while (size > 0) {
        const ssize_t n = ::read(fd, p, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        p += n;
        size -= size_t(n);
    }
    return true;
}

/// The server's own command line, padded: children write theirs over it, so that ps and
/// /proc/PID/cmdline show what they run and not `--fork-server`.
constexpr size_t CommandLineRoom = 2048;

void showCommandLine(int argc, char **argv, const std::string &request)
{
    char *const begin = argv[0];
    char *const end = argv[argc - 1] + std::strlen(argv[argc - 1]);
    const size_t room = size_t(end - begin);
    const size_t shown = std::min(room, request.size());
    std::memcpy(begin, request.data(), shown);
    std::memset(begin + shown, 0, room - shown + 1);
}

/// In a new child: the program's main with the request's arguments, as if started by exec.
[[noreturn]] void runChild(int fd, std::string request, int argc, char **argv, int (*run)(int, char **))
{
    ::close(fd);
    showCommandLine(argc, argv, request);
    std::signal(SIGCHLD, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    pthread_sigmask(SIG_SETMASK, &none, nullptr);
    std::vector<char *> arguments;
    for (size_t start = 0; start < request.size();) {
        arguments.push_back(request.data() + start);
        start = request.find('\0', start) + 1;
    }
    if (arguments.empty())
        _exit(2);
    arguments.push_back(nullptr);
    std::exit(run(int(arguments.size() - 1), arguments.data()));
}

} // namespace

ForkServer::~ForkServer()
{
    stop();
}

bool ForkServer::start(const std::string &program)
{
    std::lock_guard lock(m_mutex);
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
        return false;
    std::string path = program;
    std::string name = "rtmanager";
    std::string option = "--fork-server";
    std::string room(CommandLineRoom, ' ');
    char *argv[] = {name.data(), option.data(), room.data(), nullptr};
    // Symbols bound once in the server rather than on first use in every child. The environment
    // is made here: after fork in a process with threads only async-signal-safe calls are allowed.
    std::vector<std::string> environment {"LD_BIND_NOW=1"};
    for (char **variable = environ; *variable; ++variable) {
        if (std::strncmp(*variable, "LD_BIND_NOW=", 12) != 0)
            environment.emplace_back(*variable);
    }
    std::vector<char *> envp;
    for (std::string &variable : environment)
        envp.push_back(variable.data());
    envp.push_back(nullptr);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0) {
        // It goes when this process goes (kill, crash or exit), and with it, by their parent
        // watch, the managers it started.
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent)
            _exit(0);
        // The server's end becomes descriptor 3 (dup2 clears close-on-exec); nothing else is kept.
        if (::dup2(fds[1], 3) < 0)
            _exit(127);
        ::execve(path.c_str(), argv, envp.data());
        _exit(127);
    }
    ::close(fds[1]);
    if (pid < 0) {
        ::close(fds[0]);
        return false;
    }
    m_fd = fds[0];
    m_pid = pid;
    return true;
}

bool ForkServer::running() const
{
    std::lock_guard lock(m_mutex);
    return m_fd >= 0;
}

pid_t ForkServer::launch(const std::vector<std::string> &arguments)
{
    std::string request;
    for (const std::string &argument : arguments) {
        request += argument;
        request += '\0';
    }
    std::lock_guard lock(m_mutex);
    if (m_fd < 0 || request.size() > MaxRequest)
        return -1;
    const auto size = std::uint32_t(request.size());
    std::int32_t pid = -1;
    if (!writeAll(m_fd, &size, sizeof size) || !writeAll(m_fd, request.data(), request.size())
        || !readAll(m_fd, &pid, sizeof pid)) {
        // The server died: the caller starts processes the slow way from now on.
        ::close(m_fd);
        m_fd = -1;
        return -1;
    }
    return pid_t(pid);
}

void ForkServer::stop()
{
    std::lock_guard lock(m_mutex);
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
}

void ForkServer::serve(int fd, int argc, char **argv, int (*run)(int, char **))
{
    // Only the server binds everything at once; its children run programs of their own.
    ::unsetenv("LD_BIND_NOW");
    // Ctrl-C in a terminal reaches the whole process group: the client decides when this ends.
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGHUP, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    std::signal(SIGPIPE, SIG_IGN);
    // Children are reaped by the kernel: one that dies at once is gone for kill(pid, 0) at once.
    std::signal(SIGCHLD, SIG_IGN);
    for (;;) {
        std::uint32_t size = 0;
        std::string request;
        if (readAll(fd, &size, sizeof size) && size <= MaxRequest) {
            request.resize(size);
            if (readAll(fd, request.data(), size)) {
                const pid_t pid = ::fork();
                if (pid == 0)
                    runChild(fd, std::move(request), argc, argv, run);
                const auto answer = std::int32_t(pid);
                if (writeAll(fd, &answer, sizeof answer))
                    continue;
            }
        }
        break;
    }
    // The client closed its end: it ended, or it runs anew in the same process (a manager's
    // restart). Stay the parent of the processes started so far while they run, so that a restart
    // does not take them down; the client's end still ends this one (the parent-death signal).
    ::close(fd);
    while (::wait(nullptr) > 0 || errno == EINTR) {
    }
    _exit(0);
}

} // namespace Runtime

// SPDX-License-Identifier: MIT
#include "moduleprofiler.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace Runtime {

namespace {

/// How many modules are profiled at once (each in a process of its own).
constexpr std::size_t profilesAtOnce = 4;

bool fileState(const std::string &path, timespec *modified, long long *size)
{
    struct stat info
    {
    };
    if (stat(path.c_str(), &info) != 0)
        return false;
    *modified = info.st_mtim;
    *size = info.st_size;
    return true;
}

} // namespace

std::string ModuleProfiler::format(const std::vector<Properties> &factories)
{
    // rtc.conf lines, each key under the factory's index: `0.implementation_id: ConsoleIn`.
    std::string text;
    for (std::size_t i = 0; i < factories.size(); ++i) {
        for (const auto &[key, value] : factories[i].entries()) {
            std::string line = value;
            for (char &c : line) {
                if (c == '\n' || c == '\r')
                    c = ' ';
            }
            text += std::to_string(i) + '.' + key + ": " + line + '\n';
        }
    }
    return text;
}

std::vector<Properties> ModuleProfiler::parse(const std::string &text)
{
    const Properties all = Properties::parseConf(text);
    std::vector<Properties> factories;
    for (Properties factory;
         !(factory = all.subtree(std::to_string(factories.size()))).entries().empty();)
        factories.push_back(factory);
    return factories;
}

std::optional<std::vector<Properties>> ModuleProfiler::profileInProcess(const std::string &path,
                                                                        int timeoutMs) const
{
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        return std::nullopt;
    // Everything the child needs is made before fork: in a process with threads only
    // async-signal-safe calls may follow it.
    const std::string program = m_program;
    std::string name = "rtmanager", option = "--module-profile", file = path;
    char *argv[] = {name.data(), option.data(), file.data(), nullptr};
    const pid_t pid = fork();
    if (pid == 0) {
        const int quiet = open("/dev/null", O_WRONLY);
        if (dup2(fds[1], STDOUT_FILENO) < 0 || quiet < 0 || dup2(quiet, STDERR_FILENO) < 0)
            _exit(127);
        execv(program.c_str(), argv);
        _exit(127);
    }
    close(fds[1]);
    if (pid < 0) {
        close(fds[0]);
        return std::nullopt;
    }
    std::string text;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    bool ended = false;
    while (!ended) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        pollfd readable {fds[0], POLLIN, 0};
        if (left.count() <= 0 || poll(&readable, 1, int(left.count())) <= 0)
            break;
        char buffer[4096];
        const ssize_t got = read(fds[0], buffer, sizeof buffer);
        if (got > 0)
            text.append(buffer, std::size_t(got));
        ended = got == 0;
    }
    close(fds[0]);
    if (!ended)
        kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!ended)
        return std::nullopt;
    // A file that is no module, or whose init function fails, registers nothing.
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? parse(text) : std::vector<Properties>();
}

std::vector<std::vector<Properties>> ModuleProfiler::profiles(const std::vector<std::string> &paths,
                                                              int timeoutMs)
{
    std::vector<std::vector<Properties>> result(paths.size());
    std::vector<Entry> states(paths.size());
    std::vector<std::size_t> unknown;
    {
        std::lock_guard lock(m_mutex);
        for (std::size_t i = 0; i < paths.size(); ++i) {
            if (!fileState(paths[i], &states[i].modified, &states[i].size))
                continue;
            const auto known = m_known.find(paths[i]);
            if (known != m_known.end() && known->second.size == states[i].size
                && known->second.modified.tv_sec == states[i].modified.tv_sec
                && known->second.modified.tv_nsec == states[i].modified.tv_nsec)
                result[i] = known->second.factories;
            else
                unknown.push_back(i);
        }
    }
    std::vector<std::optional<std::vector<Properties>>> found(unknown.size());
    std::atomic<std::size_t> next {0};
    const auto work = [&] {
        for (std::size_t k; (k = next++) < unknown.size();)
            found[k] = profileInProcess(paths[unknown[k]], timeoutMs);
    };
    std::vector<std::thread> helpers;
    for (std::size_t i = 1; i < std::min(profilesAtOnce, unknown.size()); ++i)
        helpers.emplace_back(work);
    work();
    for (std::thread &helper : helpers)
        helper.join();
    std::lock_guard lock(m_mutex);
    for (std::size_t k = 0; k < unknown.size(); ++k) {
        if (!found[k])
            continue;
        const std::size_t i = unknown[k];
        result[i] = *found[k];
        states[i].factories = std::move(*found[k]);
        m_known[paths[i]] = std::move(states[i]);
    }
    return result;
}

} // namespace Runtime

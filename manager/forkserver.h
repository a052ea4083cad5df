// SPDX-License-Identifier: MIT
#pragma once

#include <mutex>
#include <string>
#include <sys/types.h>
#include <vector>

namespace Runtime {

/**
 * This program's file to start it again: its path when that still names the running file, else
 * /proc/self/exe. A process is called by the last part of the path it was started from (`ps`,
 * `pgrep`, `top`), so slaves started through /proc/self/exe would all be called `exe`.
 */
std::string ownExecutable();

/**
 * Starts processes of this program without paying for exec each time.
 *
 * A new manager process spends most of its start loading the shared libraries and running their
 * static initialisers (omniORB's type codes among them). A fork server is the same program,
 * started once with `--fork-server` and doing nothing else: it has all of that behind it, runs a
 * single thread and forks a child per request, which then runs the program's normal main with
 * the request's arguments. Children belong to the fork server (the kernel reaps them); it ends when
 * its client's process ends, so that children watching their parent learn that their master is
 * gone, and not before: a client that closes the connection (it runs anew in the same process)
 * leaves the server serving its children until the last of them ends.
 *
 * The client side is thread-safe; one request is sent and answered at a time.
 */
class ForkServer
{
public:
    ForkServer() = default;
    ~ForkServer();
    ForkServer(const ForkServer &) = delete;
    ForkServer &operator=(const ForkServer &) = delete;

    /// Starts `program --fork-server` (by default this program, ownExecutable()) with the server's
    /// end of the connection as descriptor 3; false when it cannot. Call it from the thread that
    /// lives as long as the process (the server follows that thread's end).
    bool start(const std::string &program = ownExecutable());
    bool running() const;
    /// The fork server's process id: the parent of every process it starts.
    pid_t pid() const { return m_pid; }

    /// A new process running main with @p arguments (argv[0] first); -1 when the server is gone.
    pid_t launch(const std::vector<std::string> &arguments);

    /// The serving side: answers requests on @p fd until it closes, then lives on while children run.
    /// @p run is the program's main, called in each child; @p argc and @p argv are the server's
    /// own, whose room each child takes for its command line.
    [[noreturn]] static void serve(int fd, int argc, char **argv, int (*run)(int argc, char **argv));

private:
    void stop();

    mutable std::mutex m_mutex;
    int m_fd = -1;
    pid_t m_pid = -1;
};

} // namespace Runtime

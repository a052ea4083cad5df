// SPDX-License-Identifier: MIT
#include <coil/Process.h>
#include <coil/stringutil.h>

#include <cerrno>
#include <cstdio>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace coil {
int launch_shell(const std::string &command)
{
    // Everything that allocates happens before fork(): a child of a threaded process may
    // only make async-signal-safe calls until it execs.
    const vstring words = parseArgs(command);
    if (words.empty() || words.front().empty())
        return -1;
    Argv argv(words);
    char **args = argv.get();

    // Fork twice so that the program is adopted by init and never lingers as a zombie.
    const pid_t child = ::fork();
    if (child < 0)
        return -1;
    if (child == 0) {
        ::setsid();
        const pid_t grandchild = ::fork();
        if (grandchild == 0) {
            ::execvp(args[0], args);
            ::_exit(127);
        }
        ::_exit(grandchild < 0 ? 1 : 0);
    }
    int status = 0;
    pid_t waited;
    do
        waited = ::waitpid(child, &status, 0);
    while (waited < 0 && errno == EINTR);
    if (waited < 0)
        return 0; // already reaped (SIGCHLD ignored): the second fork's result is unknown
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

int daemon(int nochdir, int noclose)
{
    return ::daemon(nochdir, noclose);
}

int create_process(const std::string &command, std::vector<std::string> &out)
{
    out.clear();
    FILE *pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr)
        return -1;
    std::string line;
    int c;
    while ((c = std::fgetc(pipe)) != EOF) {
        if (c == '\n') {
            out.push_back(line);
            line.clear();
        } else {
            line += static_cast<char>(c);
        }
    }
    if (!line.empty())
        out.push_back(line);
    ::pclose(pipe);
    return 0;
}
} // namespace coil

// SPDX-License-Identifier: MIT
#include "openrtmthroughput.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace OpenRtmThroughput {

namespace {

using Clock = std::chrono::steady_clock;

const char *const resultFile = "double-corba_cdr-sameproc.dat";

// The example creates Throughput0 itself; the file adds Throughput1 as the receiver. Sizes double
// from 1 element up to maxsize, 100 samples each. The sender deactivates itself after the largest
// size and, having no connected in-port, ends the process (which aborts on its way out, after the
// result file is complete). No name service and no manager servant: nothing outside the process
// is used.
std::string configuration(unsigned long maxElements)
{
    std::ostringstream conf;
    conf << "logger.enable: NO\n"
            "naming.enable: NO\n"
            "manager.corba_servant: NO\n"
            "corba.endpoints: 127.0.0.1:\n"
            "corba.args: -ORBgiopMaxMsgSize 209715200\n"
            "manager.components.precreate: Throughput\n"
            "manager.components.preconnect: Throughput0.out?port=Throughput1.in"
            "&dataflow_type=push&interface_type=corba_cdr&subscription_type=flush\n"
            "manager.components.preactivation: Throughput0\n"
            "example.Throughput.conf.default.datatype: double\n"
            "example.Throughput.conf.default.filesuffix: -sameproc\n"
            "example.Throughput.conf.default.maxsize: "
         << maxElements << '\n';
    return conf.str();
}

bool writeFile(const std::string &path, const std::string &text)
{
    std::ofstream out(path);
    out << text;
    return bool(out);
}

std::string readFile(const std::string &path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void removeFolder(const std::string &dir)
{
    if (DIR *d = opendir(dir.c_str())) {
        while (const dirent *entry = readdir(d)) {
            const std::string name = entry->d_name;
            if (name != "." && name != "..")
                unlink((dir + '/' + name).c_str());
        }
        closedir(d);
    }
    rmdir(dir.c_str());
}

/// The environment of this process with the prefix's libraries first on LD_LIBRARY_PATH.
std::vector<std::string> environmentWith(const std::string &prefix)
{
    const char *old = std::getenv("LD_LIBRARY_PATH");
    std::vector<std::string> result {"LD_LIBRARY_PATH=" + prefix + "/lib"
                                     + (old && *old ? std::string(":") + old : "")};
    for (char **entry = environ; *entry != nullptr; ++entry) {
        if (std::strncmp(*entry, "LD_LIBRARY_PATH=", 16) != 0)
            result.emplace_back(*entry);
    }
    return result;
}

/// Starts @p program in @p dir with the prefix's libraries; its output goes to the returned pipe.
pid_t start(const std::string &program, const std::string &prefix, const std::string &dir,
            int *output)
{
    // Everything the child needs is made before fork(): this process has threads (its ORB), so the
    // child may only make async-signal-safe calls until exec.
    std::vector<std::string> environment = environmentWith(prefix);
    std::vector<char *> envp;
    for (std::string &entry : environment)
        envp.push_back(&entry[0]);
    envp.push_back(nullptr);
    std::string config = "rtc.conf";
    std::string option = "-f";
    std::string path = program;
    char *const argv[] = {&path[0], &option[0], &config[0], nullptr};
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    const pid_t pid = fork();
    if (pid == 0) {
        // Its own process group, so that a timeout ends everything it started; and it dies with
        // the benchmark.
        setpgid(0, 0);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        close(fds[0]);
        close(fds[1]);
        if (chdir(dir.c_str()) == 0)
            execve(argv[0], argv, envp.data());
        _exit(127);
    }
    close(fds[1]);
    if (pid < 0) {
        close(fds[0]);
        return -1;
    }
    *output = fds[0];
    return pid;
}

/// Reads the child's output until it closes or the deadline passes; false on the deadline.
bool drainUntilClosed(int fd, Clock::time_point deadline, std::string *log)
{
    char buffer[4096];
    for (;;) {
        const auto left
            = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        if (left.count() <= 0)
            return false;
        pollfd p {fd, POLLIN, 0};
        const int ready = poll(&p, 1, int(left.count()));
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0)
            return false;
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n <= 0)
            return true;
        // Only the end matters when something goes wrong.
        log->append(buffer, size_t(n));
        if (log->size() > 65536)
            log->erase(0, log->size() - 16384);
    }
}

} // namespace

std::string programIn(const std::string &prefix)
{
    const std::string program
        = prefix + "/share/openrtm-2.1/components/c++/examples/ThroughputComp";
    struct stat info
    {
    };
    return stat(program.c_str(), &info) == 0 ? program : std::string();
}

std::vector<Row> parseResults(const std::string &text)
{
    std::vector<Row> rows;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream in(line);
        Row row;
        double min = 0, max = 0, mean = 0, stddev = 0, mbps = 0;
        if (line.empty() || line[0] == '#'
            || !(in >> row.elements >> min >> max >> mean >> stddev >> mbps))
            continue;
        row.minUs = min * 1e6;
        row.maxUs = max * 1e6;
        row.meanUs = mean * 1e6;
        row.stddevUs = stddev * 1e6;
        row.mibPerSecond = mbps / 8;
        rows.push_back(row);
    }
    return rows;
}

Run runSameProcess(const std::string &prefix, unsigned long maxElements, int timeoutSeconds)
{
    Run run;
    const std::string program = programIn(prefix);
    if (program.empty()) {
        run.error = "no ThroughputComp in " + prefix;
        return run;
    }
    const char *tmp = std::getenv("TMPDIR");
    std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/openrtm-throughput-XXXXXX";
    if (mkdtemp(&dir[0]) == nullptr) {
        run.error = "cannot create a temporary folder";
        return run;
    }
    if (!writeFile(dir + "/rtc.conf", configuration(maxElements))) {
        run.error = "cannot write " + dir + "/rtc.conf";
        removeFolder(dir);
        return run;
    }
    int output = -1;
    const pid_t pid = start(program, prefix, dir, &output);
    if (pid < 0) {
        run.error = "cannot start " + program;
        removeFolder(dir);
        return run;
    }
    std::string log;
    const bool ended
        = drainUntilClosed(output, Clock::now() + std::chrono::seconds(timeoutSeconds), &log);
    close(output);
    if (!ended)
        kill(-pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    run.rows = parseResults(readFile(dir + '/' + resultFile));
    if (!ended)
        run.error = "stopped after " + std::to_string(timeoutSeconds) + " s";
    else if (run.rows.empty())
        run.error = "no results; its output ended with: "
            + log.substr(log.size() > 400 ? log.size() - 400 : 0);
    removeFolder(dir);
    return run;
}

} // namespace OpenRtmThroughput

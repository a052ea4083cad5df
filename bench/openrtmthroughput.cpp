// SPDX-License-Identifier: MIT
#include "openrtmthroughput.h"

#include <algorithm>
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

// Settings both placements share. Sizes double from 1 element up to maxsize, 100 samples each. No
// name service: nothing outside the run is used.
std::string commonConfiguration(unsigned long maxElements, const char *suffix)
{
    std::ostringstream conf;
    conf << "logger.enable: NO\n"
            "naming.enable: NO\n"
            "corba.args: -ORBgiopMaxMsgSize 209715200\n"
            "example.Throughput.conf.default.datatype: double\n"
            "example.Throughput.conf.default.filesuffix: "
         << suffix << "\n"
         << "example.Throughput.conf.default.maxsize: " << maxElements << '\n';
    return conf.str();
}

// The example creates Throughput0 itself; the file adds Throughput1 as the receiver. The sender
// deactivates itself after the largest size and, having no connected in-port, ends the process
// (which aborts on its way out, after the result file is complete). No manager servant.
std::string sameProcessConfiguration(unsigned long maxElements)
{
    return commonConfiguration(maxElements, "-sameproc")
        + "manager.corba_servant: NO\n"
          "corba.endpoints: 127.0.0.1:\n"
          "manager.components.precreate: Throughput\n"
          "manager.components.preconnect: Throughput0.out?port=Throughput1.in"
          "&dataflow_type=push&interface_type=corba_cdr&subscription_type=flush\n"
          "manager.components.preactivation: Throughput0\n";
}

// The example creates Throughput0 in each process, its manager reachable at corbaloc:iiop:127.0.0.1:PORT/manager so
// that the caller can connect and activate. A manager that is not a master looks for one at
// corba.master_manager when it starts: a port nobody listens on keeps it on its own. The receiver
// ends its process after the largest size; the sender deactivates itself then and, having no
// connected in-port, ends its own.
std::string twoProcessConfiguration(unsigned long maxElements, unsigned port, unsigned noMaster)
{
    return commonConfiguration(maxElements, "-twoproc") + "corba.endpoints: 127.0.0.1:"
        + std::to_string(port) + "\ncorba.master_manager: 127.0.0.1:" + std::to_string(noMaster)
        + '\n';
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

/// One run of the example program in a temporary folder of its own, killed with everything it
/// started when it is not over by the deadline or when the run is abandoned.
class ExampleProcess
{
public:
    explicit ExampleProcess(std::string prefix) : m_prefix(std::move(prefix)) {}
    ~ExampleProcess()
    {
        stop();
        if (!m_dir.empty())
            removeFolder(m_dir);
    }
    ExampleProcess(const ExampleProcess &) = delete;
    ExampleProcess &operator=(const ExampleProcess &) = delete;

    /// Writes @p configuration as its rtc.conf and starts it; false with @p error set on failure.
    bool start(const std::string &configuration, std::string *error)
    {
        const std::string program = programIn(m_prefix);
        if (program.empty()) {
            *error = "no ThroughputComp in " + m_prefix;
            return false;
        }
        const char *tmp = std::getenv("TMPDIR");
        m_dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/openrtm-throughput-XXXXXX";
        if (mkdtemp(&m_dir[0]) == nullptr) {
            m_dir.clear();
            *error = "cannot create a temporary folder";
            return false;
        }
        if (!writeFile(m_dir + "/rtc.conf", configuration)) {
            *error = "cannot write " + m_dir + "/rtc.conf";
            return false;
        }
        m_pid = OpenRtmThroughput::start(program, m_prefix, m_dir, &m_output);
        if (m_pid < 0) {
            *error = "cannot start " + program;
            return false;
        }
        return true;
    }

    /**
     * Reads the output of every process in @p processes until all have closed it (ended) or
     * @p deadline passes; false on the deadline. All are read together: the example writes a
     * line per sample, and a full pipe would stop it.
     */
    static bool awaitEnd(const std::vector<ExampleProcess *> &processes, Clock::time_point deadline)
    {
        for (;;) {
            std::vector<pollfd> open;
            for (ExampleProcess *process : processes) {
                if (process->m_output >= 0)
                    open.push_back({process->m_output, POLLIN, 0});
            }
            if (open.empty())
                return true;
            const auto left
                = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
            if (left.count() <= 0)
                return false;
            const int ready = poll(open.data(), open.size(), int(left.count()));
            if (ready < 0 && errno == EINTR)
                continue;
            if (ready <= 0)
                return false;
            for (const pollfd &p : open) {
                if (p.revents != 0)
                    processOf(processes, p.fd)->readOutput();
            }
        }
    }

    /// Stops the program and reads @p resultFile's rows into @p run, with the reason when there
    /// are none (@p ended: whether it ended by itself before the deadline). Without a file name
    /// it only stops the program.
    void finish(bool ended, int timeoutSeconds, const std::string &resultFile, Run *run)
    {
        stop();
        if (resultFile.empty())
            return;
        run->rows = parseResults(readFile(m_dir + '/' + resultFile));
        if (!ended)
            run->error = "stopped after " + std::to_string(timeoutSeconds) + " s";
        else if (run->rows.empty())
            run->error = "no results; its output ended with: "
                + m_log.substr(m_log.size() > 400 ? m_log.size() - 400 : 0);
    }

private:
    static ExampleProcess *processOf(const std::vector<ExampleProcess *> &processes, int fd)
    {
        return *std::find_if(processes.begin(), processes.end(),
                             [fd](const ExampleProcess *p) { return p->m_output == fd; });
    }

    /// Reads what is there; closes the pipe at its end.
    void readOutput()
    {
        char buffer[4096];
        const ssize_t n = read(m_output, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            return;
        if (n <= 0) {
            close(m_output);
            m_output = -1;
            return;
        }
        // Only the end matters when something goes wrong.
        m_log.append(buffer, size_t(n));
        if (m_log.size() > 65536)
            m_log.erase(0, m_log.size() - 16384);
    }

    void stop()
    {
        if (m_output >= 0) {
            close(m_output);
            m_output = -1;
        }
        if (m_pid > 0) {
            // Gone already when it ended on its own; then this only reaps it.
            kill(-m_pid, SIGKILL);
            int status = 0;
            waitpid(m_pid, &status, 0);
            m_pid = -1;
        }
    }

    std::string m_prefix;
    std::string m_dir;
    pid_t m_pid = -1;
    int m_output = -1;
    std::string m_log;
};

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
    ExampleProcess process(prefix);
    const auto deadline = Clock::now() + std::chrono::seconds(timeoutSeconds);
    if (process.start(sameProcessConfiguration(maxElements), &run.error))
        process.finish(ExampleProcess::awaitEnd({&process}, deadline), timeoutSeconds,
                       "double-corba_cdr-sameproc.dat", &run);
    return run;
}

Run runTwoProcesses(const std::string &prefix, unsigned long maxElements, int timeoutSeconds,
                    const Ports &ports, const Connect &connect)
{
    Run run;
    ExampleProcess sender(prefix), receiver(prefix);
    const auto deadline = Clock::now() + std::chrono::seconds(timeoutSeconds);
    if (!receiver.start(twoProcessConfiguration(maxElements, ports.receiver, ports.noMaster),
                        &run.error)
        || !sender.start(twoProcessConfiguration(maxElements, ports.sender, ports.noMaster),
                         &run.error))
        return run;
    run.error = connect(ports);
    if (!run.error.empty())
        return run;
    const bool ended = ExampleProcess::awaitEnd({&sender, &receiver}, deadline);
    sender.finish(ended, timeoutSeconds, {}, &run);
    receiver.finish(ended, timeoutSeconds, "double-corba_cdr-twoproc.dat", &run);
    return run;
}

} // namespace OpenRtmThroughput

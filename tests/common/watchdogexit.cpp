// SPDX-License-Identifier: MIT
//
// Linked into every test program (rtstudio_add_test in tests/CMakeLists.txt).
//
// Qt Test runs the test functions under a watchdog, a detached QThread named "QtTest Watchdog".
// When the run ends, Qt stops it and waits for it, but that wait returns once the thread has
// finished its run, before the thread's own exit: its thread-local cleanup, which releases the
// thread's QThreadData (152 bytes), comes after. A process that returns from main first can run
// LeakSanitizer's check at exit while that cleanup is still pending, and the asan suite has seen
// that report under load. So, as the process exits, this waits (bounded) until no thread of that
// name is left; on an idle machine the thread is long gone and the wait costs one directory read.

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include <dirent.h>

namespace {

bool watchdogThreadAlive()
{
    DIR *tasks = ::opendir("/proc/self/task");
    if (!tasks)
        return false;
    bool alive = false;
    while (const dirent *entry = ::readdir(tasks)) {
        if (entry->d_name[0] == '.')
            continue;
        std::ifstream comm(std::string("/proc/self/task/") + entry->d_name + "/comm");
        std::string name;
        if (std::getline(comm, name) && name == "QtTest Watchdog") {
            alive = true;
            break;
        }
    }
    ::closedir(tasks);
    return alive;
}

struct WatchdogExit
{
    ~WatchdogExit()
    {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        while (watchdogThreadAlive() && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
};

// Destroyed at exit, before the sanitizer's own exit handler (registered earlier, run later).
const WatchdogExit watchdogExit;

} // namespace

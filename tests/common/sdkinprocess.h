// SPDX-License-Identifier: MIT
// An RTC::Manager of the component SDK inside the test process, as the SDK's tests use it: no name
// server and no master, serving on a free loopback port, run by its own thread.
#pragma once

#include <rtm/Manager.h>
#include <rtm/RTObject.h>

#include <QByteArrayList>
#include <QTest>

#include <vector>

namespace SdkTest {

/**
 * Initializes, activates and runs (in a thread of its own) the process's RTC::Manager with
 * @p options added as `-o key:value`; nullptr when it could not be initialized or activated.
 */
inline RTC::Manager *startInProcessManager(const char *program, const QByteArrayList &options = {})
{
    QByteArrayList arguments{program,       "-o", "naming.enable:NO", "-o", "corba.master_manager:", "-o",
                             "corba.endpoints:127.0.0.1:", "-o", "logger.log_level:ERROR"};
    for (const QByteArray &option : options)
        arguments << "-o" << option;
    arguments << "-f" << "/nonexistent/rtc.conf" << "-i";
    std::vector<char *> argv;
    for (QByteArray &argument : arguments)
        argv.push_back(argument.data());
    RTC::Manager *manager = RTC::Manager::init(int(argv.size()), argv.data());
    if (manager == nullptr || !manager->activateManager())
        return nullptr;
    manager->runManager(true);
    return manager;
}

/// Deletes every component (waiting a bounded time until they are gone), ends the manager and
/// waits for its thread, as a component program's manager shuts down.
inline bool stopInProcessManager(RTC::Manager *manager)
{
    if (manager == nullptr)
        return true;
    for (RTC::RTObject_impl *component : manager->getComponents())
        manager->deleteComponent(component);
    const bool deleted = QTest::qWaitFor([manager] { return manager->getComponents().empty(); }, 5000);
    RTC::Manager::terminate();
    manager->join();
    return deleted;
}

} // namespace SdkTest

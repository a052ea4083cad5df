// SPDX-License-Identifier: MIT
#pragma once

#include <omniORB4/CORBA.h>

#include <QString>
#include <QStringList>

#include <functional>

namespace SdkFsmTest {

/// One step of the traffic light's scenario: a button, what the view then shows, the state.
struct TrafficStep
{
    QString button;
    std::function<bool(long)> wanted;
    QString state; ///< the machine's current state afterwards
    QString why;
};

/**
 * on (Dark → Running, whose init chooses Red), go (Green), fault (Flashing, its TimedLong in the
 * top state's box), repair (Running's history: Green), off (Dark), on (Running's init: Red).
 */
QList<TrafficStep> trafficScenario();

/**
 * Drives a TrafficLight component (tests/sdkmodules/trafficlight) from outside, as a user would
 * with rtctl: rtmanager's built-in ConsoleIn components are its buttons, one connection to its
 * EventInPort per event, and a ConsoleOut ("StateView") shows what the light writes on its
 * "state" OutPort. A button sends its event while it is active.
 */
class TrafficLightDriver
{
public:
    /// rtmanager's `manager.components.precreate` value: the buttons and the view.
    static QString precreate();

    /// @p namingServer is `host:port`; @p ours the host context of rtmanager's components,
    /// @p light the full rtctl path of the TrafficLight.
    TrafficLightDriver(CORBA::ORB_ptr orb, const QString &namingServer, const QString &ours, const QString &light);

    /// Connects the buttons and the view; the rtctl error when one connection fails.
    QString connectAll();
    /// Activates the light and the view.
    QString activate();
    /// Keeps @p button active until the view shows a value @p wanted accepts (20 s at most);
    /// the values seen on the way in @p seen.
    bool press(const QString &button, const std::function<bool(long)> &wanted, QString *seen);
    /// A value from the status list of the component at @p path (empty when unreachable).
    QString status(const QString &path, const char *name) const;
    QString lastValue() const { return status(view(), "last_value"); }
    QString path(const QString &name) const;

private:
    QString view() const { return path(QStringLiteral("StateView")); }
    QString run(const QStringList &arguments) const;

    CORBA::ORB_var m_orb;
    QString m_namingServer;
    QString m_ours;
    QString m_light;
};

} // namespace SdkFsmTest

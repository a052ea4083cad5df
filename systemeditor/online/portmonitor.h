// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QHash>
#include <QJsonValue>
#include <QList>
#include <QWidget>

#include <deque>

class QCheckBox;
class QChart;
class QChartView;
class QLabel;
class QListWidget;
class QSpinBox;
class QSplitter;
class QTableWidget;
class QThread;
class QValueAxis;

namespace SystemEditor {

class PortMonitorWorker;

/// One decoded sample of a watched port.
struct MonitorSample
{
    qint64 receivedMs = 0;
    QJsonValue value;
    QString text; ///< as `rtctl print` shows it
};

/**
 * The Port Monitor: the samples of data OutPorts as they flow, like rtshell's rtprint with a live
 * plot. Each watched port gets a connector of its own to an InPortCdr object of this process; a
 * worker thread drains them and decodes the samples by the port's IDL type (OpenRTM's IDL), so the
 * GUI thread makes no remote call. For the chosen port it shows a table of the latest samples
 * and a plot of their numeric fields over a time window; Rate keeps at most that many samples a
 * second of each port (as rtprint's --rate; 0 keeps all), Pause freezes the view (samples keep
 * arriving), Export writes the kept samples as CSV. Removing a port or closing the view removes
 * its connector.
 */
class PortMonitor : public QWidget
{
    Q_OBJECT

public:
    explicit PortMonitor(QWidget *parent = nullptr);
    ~PortMonitor() override;

    /// Starts watching `port` of the component at `componentPath` (a tree path); a port already
    /// watched is just selected.
    void watch(const QString &componentPath, const Corba::PortInfo &port);
    /// Folders with IDL files besides OpenRTM's, for ports of user data types.
    void setIdlDirectories(const QStringList &directories);
    /// Stops watching (removes the connector).
    void unwatch(const QString &key);
    /// `<component path>:<port>` of the watched ports, in the order they were added.
    QStringList watched() const { return m_order; }
    QString current() const;
    void setCurrent(const QString &key);

    /// The samples kept for a port (within the time window), oldest first.
    QList<MonitorSample> samples(const QString &key) const;
    /// How many samples of a port arrived since it is watched.
    quint64 received(const QString &key) const { return m_watched.value(key).received; }
    /// The numeric fields plotted for a port (`data`, `data[0]`, `data.position.x`, …).
    QStringList fields(const QString &key) const;
    /// A port's state: empty while fine, else why it is not watched (refused, unknown type, …).
    QString problem(const QString &key) const;

    void setPaused(bool paused);
    bool isPaused() const;
    /// The plotted time window in seconds.
    void setWindowSeconds(int seconds);
    /// At most this many samples a second are kept of each port; 0 keeps every sample.
    void setRate(int samplesPerSecond);
    /// Writes the kept samples of `key` as CSV (time in seconds since the epoch, then each field).
    bool exportCsv(const QString &key, const QString &path, QString *error) const;

    QTableWidget *table() const { return m_table; }
    QChart *chart() const { return m_chart; }

protected:
    void showEvent(QShowEvent *event) override;

signals:
    /// A port's connector was made (problem empty) or refused.
    void watchStarted(const QString &key, const QString &problem);
    /// New samples of a port were shown.
    void samplesShown(const QString &key);
    void statusMessage(const QString &message);

private:
    friend class PortMonitorWorker;

    struct Watched
    {
        QString type; ///< the IDL type's scoped name
        QString problem;
        std::deque<MonitorSample> samples;
        QStringList fields;
        quint64 received = 0;
        qint64 lastKeptMs = 0;
    };

    void buildUi();
    void receive(const QString &key, const QList<MonitorSample> &batch);
    void opened(const QString &key, const QString &type, const QString &problem);
    void refreshView();
    void prune(Watched &watched, qint64 nowMs) const;
    void exportCurrent();

    QThread *m_thread;
    PortMonitorWorker *m_worker;
    QHash<QString, Watched> m_watched;
    QStringList m_order;
    QStringList m_idlDirectories;

    QSplitter *m_splitter = nullptr;
    bool m_splitSet = false;
    QListWidget *m_ports = nullptr;
    QLabel *m_status = nullptr;
    QTableWidget *m_table = nullptr;
    QChart *m_chart = nullptr;
    QChartView *m_chartView = nullptr;
    QValueAxis *m_timeAxis = nullptr;
    QValueAxis *m_valueAxis = nullptr;
    QCheckBox *m_pause = nullptr;
    QSpinBox *m_window = nullptr;
    QSpinBox *m_rate = nullptr;
};

} // namespace SystemEditor

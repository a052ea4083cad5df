// SPDX-License-Identifier: MIT
#include "portmonitor.h"

#include "cdrcodec.h"
#include "corbaerror.h"
#include "idltypelibrary.h"
#include "installation.h"
#include "porttap.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QDateTime>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonObject>
#include <QLabel>
#include <QLineSeries>
#include <QListWidget>
#include <QPointer>
#include <QPushButton>
#include <QSaveFile>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QThread>
#include <QTimer>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

namespace SystemEditor {

namespace {

constexpr int MaxFields = 16;
constexpr int TableRows = 100;
constexpr size_t MaxKept = 20000;

/// The numbers of a sample by field path, the timestamp left out.
void flatten(const QJsonValue &value, const QString &path, QList<std::pair<QString, double>> *out)
{
    if (out->size() >= MaxFields)
        return;
    if (value.isDouble()) {
        out->append({path, value.toDouble()});
    } else if (value.isBool()) {
        out->append({path, value.toBool() ? 1.0 : 0.0});
    } else if (value.isObject()) {
        const QJsonObject object = value.toObject();
        for (auto it = object.constBegin(); it != object.constEnd(); ++it) {
            if (path.isEmpty() && it.key() == QLatin1String("tm"))
                continue;
            flatten(it.value(), path.isEmpty() ? it.key() : path + QLatin1Char('.') + it.key(), out);
        }
    } else if (value.isArray()) {
        const QJsonArray array = value.toArray();
        for (qsizetype i = 0; i < array.size(); ++i)
            flatten(array.at(i), QStringLiteral("%1[%2]").arg(path).arg(i), out);
    }
}

QString timeText(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("HH:mm:ss.zzz"));
}

} // namespace

/// Lives in the monitor's own thread: makes and removes the connectors, drains and decodes.
class PortMonitorWorker : public QObject
{
public:
    explicit PortMonitorWorker(PortMonitor *monitor)
        : m_monitor(monitor)
    { }

    void start()
    {
        loadIdl({});
        m_drain = new QTimer(this);
        m_drain->setInterval(50);
        connect(m_drain, &QTimer::timeout, this, &PortMonitorWorker::drain);
        m_drain->start();
    }

    void loadIdl(const QStringList &extra)
    {
        m_library = std::make_unique<Codegen::IdlTypeLibrary>(
            QStringList {Codegen::Installation::bundledIdlDirectory()} + extra);
        m_codec = std::make_unique<Codegen::CdrCodec>(m_library->model());
    }

    void open(const QString &key, const Corba::PortInfo &port, const QString &path)
    {
        QString type;
        QString problem;
        try {
            const QString dataType = Corba::propertyValue(port.properties, QStringLiteral("dataport.data_type"));
            type = Codegen::CdrCodec::typeName(dataType);
            if (!m_codec->knows(type))
                throw Corba::Error(Corba::Error::Kind::NotFound,
                                   PortMonitor::tr("%1: data type %2 is in none of the IDL files").arg(path, dataType));
            m_taps[key] = std::make_unique<Corba::PortTap>(port, Corba::Properties(), path);
            m_types[key] = type;
        } catch (const Corba::Error &e) {
            problem = e.message();
        }
        report([key, type, problem](PortMonitor *monitor) { monitor->opened(key, type, problem); });
    }

    void close(const QString &key)
    {
        m_taps.erase(key); // removes the connector
        m_types.remove(key);
    }

    void closeAll()
    {
        m_drain->stop();
        m_taps.clear();
    }

private:
    void drain()
    {
        for (auto &[key, tap] : m_taps) {
            QList<MonitorSample> batch;
            const QString type = m_types.value(key);
            for (int i = 0; i < 5000; ++i) {
                const std::optional<Corba::PortSample> sample = tap->next(0);
                if (!sample)
                    break;
                QString problem;
                const QJsonValue value = m_codec->decode(type, sample->cdr, tap->littleEndian(), &problem);
                if (problem.isEmpty())
                    batch.append({sample->receivedMs, value, m_codec->toText(type, value)});
            }
            if (!batch.isEmpty())
                report([key = key, batch](PortMonitor *monitor) { monitor->receive(key, batch); });
        }
    }

    template <typename F>
    void report(F &&f)
    {
        QPointer<PortMonitor> monitor = m_monitor;
        QMetaObject::invokeMethod(m_monitor, [monitor, f = std::forward<F>(f)] {
            if (monitor)
                f(monitor);
        });
    }

    PortMonitor *m_monitor;
    std::unique_ptr<Codegen::IdlTypeLibrary> m_library;
    std::unique_ptr<Codegen::CdrCodec> m_codec;
    std::map<QString, std::unique_ptr<Corba::PortTap>> m_taps;
    QHash<QString, QString> m_types;
    QTimer *m_drain = nullptr;
};

PortMonitor::PortMonitor(QWidget *parent)
    : QWidget(parent)
    , m_thread(new QThread(this))
    , m_worker(new PortMonitorWorker(this))
{
    buildUi();
    m_thread->setObjectName(QStringLiteral("PortMonitor"));
    m_worker->moveToThread(m_thread);
    m_thread->start();
    QMetaObject::invokeMethod(m_worker, [worker = m_worker] { worker->start(); });
    auto *refresh = new QTimer(this);
    refresh->setInterval(100);
    connect(refresh, &QTimer::timeout, this, &PortMonitor::refreshView);
    refresh->start();
}

PortMonitor::~PortMonitor()
{
    // The connectors go before the thread does (each removal bounded by the call timeout).
    QMetaObject::invokeMethod(m_worker, [worker = m_worker] { worker->closeAll(); },
                              Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
    delete m_worker;
}

void PortMonitor::buildUi()
{
    m_ports = new QListWidget(this);
    m_ports->setObjectName(QStringLiteral("portMonitorPorts"));
    auto *remove = new QPushButton(tr("&Remove"), this);
    remove->setObjectName(QStringLiteral("portMonitorRemove"));
    connect(remove, &QPushButton::clicked, this, [this] {
        if (!current().isEmpty())
            unwatch(current());
    });
    m_pause = new QCheckBox(tr("&Pause"), this);
    m_pause->setObjectName(QStringLiteral("portMonitorPause"));
    m_window = new QSpinBox(this);
    m_window->setRange(1, 600);
    m_window->setValue(10);
    m_window->setSuffix(tr(" s"));
    m_window->setToolTip(tr("How many seconds of samples are kept and plotted"));
    m_rate = new QSpinBox(this);
    m_rate->setObjectName(QStringLiteral("portMonitorRate"));
    m_rate->setRange(0, 1000);
    m_rate->setValue(0);
    m_rate->setSpecialValueText(tr("all"));
    m_rate->setSuffix(tr(" /s"));
    m_rate->setToolTip(tr("At most this many samples a second are kept of each port (all: every sample)"));
    auto *exportButton = new QPushButton(tr("E&xport CSV…"), this);
    connect(exportButton, &QPushButton::clicked, this, &PortMonitor::exportCurrent);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);

    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    auto *hint = new QLabel(tr("Watched ports (pick one on an online diagram: Monitor Port)"), left);
    hint->setWordWrap(true);
    leftLayout->addWidget(hint);
    leftLayout->addWidget(m_ports);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(remove);
    buttons->addWidget(exportButton);
    leftLayout->addLayout(buttons);
    auto *controls = new QHBoxLayout;
    controls->addWidget(m_pause);
    controls->addWidget(new QLabel(tr("Window:"), left));
    controls->addWidget(m_window);
    controls->addWidget(new QLabel(tr("Rate:"), left));
    controls->addWidget(m_rate);
    leftLayout->addLayout(controls);
    leftLayout->addWidget(m_status);

    m_table = new QTableWidget(0, 2, this);
    m_table->setObjectName(QStringLiteral("portMonitorTable"));
    m_table->setHorizontalHeaderLabels({tr("Received"), tr("Value")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setWordWrap(false);
    m_table->setTextElideMode(Qt::ElideRight);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);

    m_chart = new QChart;
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_timeAxis = new QValueAxis(m_chart);
    m_timeAxis->setTitleText(tr("Seconds"));
    m_timeAxis->setLabelFormat(QStringLiteral("%.0f"));
    m_timeAxis->setTickCount(6);
    m_valueAxis = new QValueAxis(m_chart);
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    m_chart->addAxis(m_valueAxis, Qt::AlignLeft);
    m_chartView = new QChartView(m_chart, this);
    m_chartView->setRenderHint(QPainter::Antialiasing);
    m_chartView->setMinimumHeight(160);

    auto *splitter = new QSplitter(this);
    m_splitter = splitter;
    splitter->addWidget(left);
    splitter->addWidget(m_table);
    splitter->addWidget(m_chartView);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    splitter->setStretchFactor(2, 2);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter);
    connect(m_ports, &QListWidget::currentRowChanged, this, [this] { refreshView(); });
}

void PortMonitor::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_splitSet)
        return;
    // The list, the table and the plot share the width a quarter, a third and the rest.
    m_splitSet = true;
    const int width = m_splitter->width();
    m_splitter->setSizes({width / 4, width / 3, width - width / 4 - width / 3});
}

void PortMonitor::watch(const QString &componentPath, const Corba::PortInfo &port)
{
    const QString key = componentPath + QLatin1Char(':') + port.shortName();
    if (!m_watched.contains(key)) {
        if (!port.isDataOut()) {
            emit statusMessage(tr("%1 is no OutPort: only what an OutPort sends can be watched.").arg(key));
            return;
        }
        m_watched.insert(key, Watched());
        m_order.append(key);
        // The component's name and the port; the whole path in the tool tip.
        auto *item = new QListWidgetItem(key.section(QLatin1Char('/'), -1), m_ports);
        item->setToolTip(key);
        QMetaObject::invokeMethod(m_worker, [worker = m_worker, key, port] { worker->open(key, port, key); });
    }
    setCurrent(key);
}

void PortMonitor::setIdlDirectories(const QStringList &directories)
{
    if (directories == m_idlDirectories)
        return;
    m_idlDirectories = directories;
    QMetaObject::invokeMethod(m_worker, [worker = m_worker, directories] { worker->loadIdl(directories); });
}

void PortMonitor::unwatch(const QString &key)
{
    if (!m_watched.remove(key))
        return;
    const qsizetype index = m_order.indexOf(key);
    m_order.removeAt(index);
    delete m_ports->takeItem(int(index));
    QMetaObject::invokeMethod(m_worker, [worker = m_worker, key] { worker->close(key); });
    refreshView();
}

QString PortMonitor::current() const
{
    const int row = m_ports->currentRow();
    return row >= 0 && row < m_order.size() ? m_order.at(row) : QString();
}

void PortMonitor::setCurrent(const QString &key)
{
    m_ports->setCurrentRow(int(m_order.indexOf(key)));
}

QList<MonitorSample> PortMonitor::samples(const QString &key) const
{
    const auto it = m_watched.constFind(key);
    return it == m_watched.constEnd() ? QList<MonitorSample>()
                                      : QList<MonitorSample>(it->samples.begin(), it->samples.end());
}

QStringList PortMonitor::fields(const QString &key) const
{
    return m_watched.value(key).fields;
}

QString PortMonitor::problem(const QString &key) const
{
    return m_watched.value(key).problem;
}

void PortMonitor::setPaused(bool paused)
{
    m_pause->setChecked(paused);
}

bool PortMonitor::isPaused() const
{
    return m_pause->isChecked();
}

void PortMonitor::setWindowSeconds(int seconds)
{
    m_window->setValue(seconds);
}

void PortMonitor::setRate(int samplesPerSecond)
{
    m_rate->setValue(samplesPerSecond);
}

void PortMonitor::opened(const QString &key, const QString &type, const QString &problem)
{
    const auto it = m_watched.find(key);
    if (it == m_watched.end())
        return;
    it->type = type;
    it->problem = problem;
    emit watchStarted(key, problem);
    if (!problem.isEmpty())
        emit statusMessage(problem);
    refreshView();
}

void PortMonitor::receive(const QString &key, const QList<MonitorSample> &batch)
{
    const auto it = m_watched.find(key);
    if (it == m_watched.end())
        return;
    const int rate = m_rate->value();
    const qint64 spacingMs = rate > 0 ? 1000 / rate : 0;
    for (const MonitorSample &sample : batch) {
        if (spacingMs > 0 && !it->samples.empty() && sample.receivedMs - it->lastKeptMs < spacingMs)
            continue;
        it->samples.push_back(sample);
        it->lastKeptMs = sample.receivedMs;
    }
    it->received += quint64(batch.size());
    if (it->fields.isEmpty() && !batch.isEmpty()) {
        QList<std::pair<QString, double>> numbers;
        flatten(batch.front().value, QString(), &numbers);
        for (const auto &[field, number] : numbers)
            it->fields.append(field);
    }
    prune(*it, QDateTime::currentMSecsSinceEpoch());
}

void PortMonitor::prune(Watched &watched, qint64 nowMs) const
{
    const qint64 oldest = nowMs - qint64(m_window->value()) * 1000;
    while (!watched.samples.empty()
           && (watched.samples.front().receivedMs < oldest || watched.samples.size() > MaxKept))
        watched.samples.pop_front();
}

void PortMonitor::refreshView()
{
    const QString key = current();
    const auto it = m_watched.find(key);
    if (it == m_watched.end()) {
        m_table->setRowCount(0);
        m_chart->removeAllSeries();
        m_status->clear();
        return;
    }
    m_status->setText(it->problem.isEmpty() ? tr("%1 · %n sample(s) kept", nullptr, int(it->samples.size()))
                                                  .arg(it->type)
                                            : it->problem);
    if (isPaused())
        return;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    prune(*it, now);

    // The newest samples first.
    const int rows = int(std::min<size_t>(TableRows, it->samples.size()));
    m_table->setRowCount(rows);
    for (int row = 0; row < rows; ++row) {
        const MonitorSample &sample = it->samples[it->samples.size() - 1 - size_t(row)];
        for (const auto &[column, value] :
             {std::pair {0, timeText(sample.receivedMs)}, std::pair {1, sample.text}}) {
            QTableWidgetItem *item = m_table->item(row, column);
            if (!item) {
                item = new QTableWidgetItem;
                m_table->setItem(row, column, item);
            }
            item->setText(value);
        }
    }

    // One series per numeric field over the window, time relative to now.
    QList<QAbstractSeries *> series = m_chart->series();
    if (series.size() != it->fields.size()) {
        m_chart->removeAllSeries();
        for (const QString &field : std::as_const(it->fields)) {
            auto *line = new QLineSeries(m_chart);
            line->setName(field);
            m_chart->addSeries(line);
            line->attachAxis(m_timeAxis);
            line->attachAxis(m_valueAxis);
        }
        series = m_chart->series();
    }
    QList<QList<QPointF>> points(series.size());
    double low = 0;
    double high = 0;
    bool first = true;
    // At most about 2,000 points a series: a long window at a high rate is thinned evenly.
    const size_t stride = std::max<size_t>(1, it->samples.size() / 2000);
    for (size_t index = 0; index < it->samples.size(); index += stride) {
        const MonitorSample &sample = it->samples[index];
        QList<std::pair<QString, double>> numbers;
        flatten(sample.value, QString(), &numbers);
        const double x = double(sample.receivedMs - now) / 1000.0;
        for (qsizetype i = 0; i < numbers.size() && i < points.size(); ++i) {
            points[i].append({x, numbers[i].second});
            low = first ? numbers[i].second : std::min(low, numbers[i].second);
            high = first ? numbers[i].second : std::max(high, numbers[i].second);
            first = false;
        }
    }
    for (qsizetype i = 0; i < series.size(); ++i)
        static_cast<QLineSeries *>(series[i])->replace(points[i]);
    m_timeAxis->setRange(-m_window->value(), 0);
    const double margin = high > low ? (high - low) * 0.05 : 1.0;
    m_valueAxis->setRange(low - margin, high + margin);
    // As many ticks as labels fit one above the other: in a low plot Qt Charts would draw them as
    // "…" rather than overlap them.
    const qreal labelPitch = m_chartView->fontMetrics().height() * 1.5;
    m_valueAxis->setTickCount(std::clamp(int(m_chart->plotArea().height() / labelPitch) + 1, 2, 5));
    // Ticks at round values (…, 2000, 4000, 6000) rather than at fifths of the data's range, with
    // as many decimals as the step between them needs.
    m_valueAxis->applyNiceNumbers();
    const double step
        = (m_valueAxis->max() - m_valueAxis->min()) / std::max(1, m_valueAxis->tickCount() - 1);
    const int decimals = step > 0 ? std::max(0, int(-std::floor(std::log10(step)))) : 1;
    m_valueAxis->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
    emit samplesShown(key);
}

bool PortMonitor::exportCsv(const QString &key, const QString &path, QString *error) const
{
    const auto it = m_watched.constFind(key);
    if (it == m_watched.constEnd()) {
        *error = tr("%1 is not watched.").arg(key);
        return false;
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    file.write(("time," + it->fields.join(QLatin1Char(',')) + "\n").toUtf8());
    for (const MonitorSample &sample : it->samples) {
        QList<std::pair<QString, double>> numbers;
        flatten(sample.value, QString(), &numbers);
        QStringList cells {QString::number(double(sample.receivedMs) / 1000.0, 'f', 3)};
        for (const auto &[field, number] : numbers)
            cells.append(QString::number(number, 'g', QLocale::FloatingPointShortest));
        file.write((cells.join(QLatin1Char(',')) + QLatin1Char('\n')).toUtf8());
    }
    if (!file.commit()) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

void PortMonitor::exportCurrent()
{
    const QString key = current();
    if (key.isEmpty())
        return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Samples"), QString(),
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    emit statusMessage(exportCsv(key, path, &error) ? tr("Saved the samples of %1 to %2").arg(key, path)
                                                    : error);
}

} // namespace SystemEditor

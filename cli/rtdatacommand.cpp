// SPDX-License-Identifier: MIT
#include "rtdatacommand.h"

#include "cdrcodec.h"
#include "corbaerror.h"
#include "idltypelibrary.h"
#include "installation.h"
#include "interruptscope.h"
#include "porttap.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QThread>


namespace Cli {

using namespace Corba;

namespace {

const std::atomic_bool &s_interrupted = InterruptScope::interrupted();

/// The port's data type as a scoped IDL name, or a Corba::Error saying which IDL is missing.
QString portType(const Codegen::CdrCodec &codec, const PortInfo &port, const QString &where)
{
    const QString dataType = propertyValue(port.properties, QStringLiteral("dataport.data_type"));
    const QString type = Codegen::CdrCodec::typeName(dataType);
    if (type.isEmpty())
        throw Error(Error::Kind::Incompatible, QStringLiteral("%1: the port names no data type").arg(where));
    if (!codec.knows(type))
        throw Error(Error::Kind::NotFound,
                    QStringLiteral("%1: data type %2 is in none of the IDL files (add its folder "
                                   "with --idl-dir)")
                        .arg(where, dataType));
    return type;
}

/// OpenRTM's IDL first, then the user's folders.
QStringList idlFolders(const RtOptions &options)
{
    return QStringList {Codegen::Installation::bundledIdlDirectory()}
        + options.values.value(QStringLiteral("--idl-dir"));
}

/// The options the data commands share, checked once.
struct DataSettings
{
    qint64 count = 0; ///< -n: samples to print or record, or times to write the values
    double rate = 0; ///< -r: samples a second (0: as they come)
    double duration = 0; ///< -d: seconds to record (0: no limit)
    int linger = 500; ///< --linger: milliseconds a writing connector stays after the last sample
    Properties connector; ///< -p KEY=VALUE
};

Properties connectorSettings(const RtOptions &options, QString *error);

/// Reads -n, -r, -d, --linger and -p; the reason when one of them is wrong.
QString parseSettings(const RtOptions &options, qint64 defaultCount, DataSettings *settings)
{
    bool ok = true;
    settings->count = options.value(QStringLiteral("-n"), QString::number(defaultCount)).toLongLong(&ok);
    if (!ok || settings->count < 0)
        return QStringLiteral("-n needs a whole number");
    settings->rate = options.value(QStringLiteral("-r"), QStringLiteral("0")).toDouble(&ok);
    if (!ok || settings->rate < 0)
        return QStringLiteral("-r needs a rate in samples a second");
    settings->duration = options.value(QStringLiteral("-d"), QStringLiteral("0")).toDouble(&ok);
    if (!ok || settings->duration < 0)
        return QStringLiteral("-d needs a number of seconds");
    settings->linger = options.value(QStringLiteral("--linger"), QStringLiteral("500")).toInt(&ok);
    if (!ok || settings->linger < 0)
        return QStringLiteral("--linger needs a number of milliseconds");
    QString error;
    settings->connector = connectorSettings(options, &error);
    return error;
}

/// Opens `path` for reading, or standard input for "-"; throws the reason naming the file.
void openInput(const QString &path, QFile *file)
{
    const bool opened = path == QLatin1String("-") ? file->open(stdin, QIODevice::ReadOnly)
                                                    : (file->setFileName(path), file->open(QIODevice::ReadOnly));
    if (!opened)
        throw Error(Error::Kind::NotFound, QStringLiteral("%1: %2").arg(path, file->errorString()));
}

/// Waits `milliseconds` (or until interrupted): an InPort's unread samples go with the connector.
void linger(int milliseconds)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < milliseconds && !s_interrupted)
        QThread::msleep(ulong(std::min<qint64>(50, milliseconds - clock.elapsed())));
}

Properties connectorSettings(const RtOptions &options, QString *error)
{
    Properties properties;
    for (const QString &property : options.values.value(QStringLiteral("-p"))) {
        const qsizetype equals = property.indexOf(QLatin1Char('='));
        if (equals <= 0) {
            *error = QStringLiteral("-p needs KEY=VALUE, got '%1'").arg(property);
            return {};
        }
        properties.append({property.left(equals), property.mid(equals + 1)});
    }
    return properties;
}

} // namespace

QString RtDataCommand::name() const
{
    switch (m_mode) {
    case Mode::Print:
        return QStringLiteral("print");
    case Mode::Inject:
        return QStringLiteral("inject");
    case Mode::Log:
        break;
    }
    return QStringLiteral("log");
}

QString RtDataCommand::summary() const
{
    switch (m_mode) {
    case Mode::Print:
        return QStringLiteral("print the samples an OutPort sends");
    case Mode::Inject:
        return QStringLiteral("write samples into an InPort");
    case Mode::Log:
        break;
    }
    return QStringLiteral("record OutPorts' samples to a file and play them into InPorts");
}

QString RtDataCommand::usage() const
{
    if (m_mode == Mode::Log)
        return QStringLiteral(
            "Usage: rtctl log -o FILE [-n COUNT] [-d SECONDS] [-p KEY=VALUE]... [--idl-dir DIR]...\n"
            "                 PATH:PORT...\n"
            "       rtctl log --play FILE [-r RATE] [--linger MS] [--idl-dir DIR]... PATH:PORT...\n\n"
            "Records the samples of OutPorts (rtshell's rtlog) until COUNT samples in all, SECONDS\n"
            "or Ctrl-C, one JSON line each: {\"t\": received (ms since the epoch), \"port\", \"type\",\n"
            "\"value\"}. --play writes them into InPorts at the recorded pace (or RATE samples a\n"
            "second): the recorded ports, in the order they first appear in the file, go to the\n"
            "PATH:PORTs given, which must take the same data types.\n"
            "  -o FILE          where to record (- = standard output)\n"
            "  -n COUNT         stop after COUNT samples\n"
            "  -d SECONDS       stop after SECONDS\n"
            "  --play FILE      play a recording\n"
            "  -r RATE          play at RATE samples a second instead of the recorded pace\n"
            "  --linger MS      keep the connectors MS milliseconds after the last sample (500)\n");
    if (m_mode == Mode::Print)
        return QStringLiteral(
            "Usage: rtctl print [-n COUNT] [-r RATE] [--json] [-p KEY=VALUE]... [--idl-dir DIR]...\n"
            "                   [--timeout MS] PATH:PORT\n\n"
            "Prints each sample an OutPort sends (rtshell's rtprint), through a connector of its\n"
            "own that is removed on exit, Ctrl-C or error. Timed types print as\n"
            "`[sec.nsec] member=value …`; --json prints one JSON object per line (what\n"
            "`rtctl inject --from` reads back).\n"
            "  -n COUNT         stop after COUNT samples (default: until interrupted)\n"
            "  -r RATE          print at most RATE samples a second (the others are skipped)\n"
            "  --json           JSON lines, members in declaration order\n"
            "  -p KEY=VALUE     connector property; the default subscription type `new` never\n"
            "                   holds the component up but skips samples written in a burst,\n"
            "                   dataport.subscription_type=flush shows every one\n"
            "  --idl-dir DIR    more folders with IDL files for user data types (repeatable)\n");
    return QStringLiteral(
        "Usage: rtctl inject [-n TIMES] [-r RATE] [--from FILE] [-p KEY=VALUE]...\n"
        "                    [--idl-dir DIR]... [--timeout MS] PATH:PORT [VALUE...]\n\n"
        "Writes samples into an InPort (rtshell's rtinject), through a connector of its own that\n"
        "is removed afterwards. Each VALUE is one sample: a JSON object with the type's members\n"
        "(`{\"data\": 5}`; a timed type's tm defaults to now), or for a type with one member\n"
        "besides tm that member's value alone (`42`, `[1.5,2]`, or text for a string).\n"
        "  --from FILE      one sample per line (JSON, as `rtctl print --json` writes; - = stdin)\n"
        "  -n TIMES         write the samples TIMES times (default 1)\n"
        "  -r RATE          samples a second (default: one after the other)\n"
        "  --linger MS      keep the connector MS milliseconds after the last sample (default\n"
        "                   500): an InPort's unread samples go with the connector, so the\n"
        "                   component needs a moment to read them\n"
        "  -p KEY=VALUE     connector property\n"
        "  --idl-dir DIR    more folders with IDL files for user data types (repeatable)\n");
}

QStringList RtDataCommand::flagNames() const
{
    return m_mode == Mode::Print ? QStringList {QStringLiteral("--json")} : QStringList();
}

std::pair<PortInfo, QString> RtDataCommand::port(const QString &text) const
{
    const RtPath target = path(text);
    if (target.port.isEmpty())
        throw Error(Error::Kind::BadPath, target.toString() + QStringLiteral(": no :PORT given"));
    return {component(target).port(target.port), target.toString()};
}

QStringList RtDataCommand::optionNames() const
{
    QStringList names {QStringLiteral("-n"), QStringLiteral("-r"), QStringLiteral("-p"),
                       QStringLiteral("--idl-dir")};
    if (m_mode == Mode::Inject)
        names += {QStringLiteral("--from"), QStringLiteral("--linger")};
    if (m_mode == Mode::Log)
        names += {QStringLiteral("-o"), QStringLiteral("-d"), QStringLiteral("--play"), QStringLiteral("--linger")};
    return names;
}

int RtDataCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.isEmpty())
        return usageError(QStringLiteral("%1 needs a PATH:PORT").arg(name()), streams);
    if (m_mode == Mode::Log) {
        const bool recording = options.values.contains(QStringLiteral("-o"));
        if (recording == options.values.contains(QStringLiteral("--play")))
            return usageError(QStringLiteral("log needs either -o FILE or --play FILE"), streams);
        return recording ? record(options, streams) : play(options, streams);
    }
    if (m_mode == Mode::Print && options.positionals.size() != 1)
        return usageError(QStringLiteral("print watches one PATH:PORT"), streams);
    const auto [found, where] = port(options.positionals.first());
    return m_mode == Mode::Print ? print(options, found, where, streams)
                                 : inject(options, found, where, streams);
}

int RtDataCommand::print(const RtOptions &options, const PortInfo &port, const QString &where,
                         Streams streams)
{
    DataSettings settings;
    if (const QString error = parseSettings(options, 0, &settings); !error.isEmpty())
        return usageError(error, streams);
    const qint64 count = settings.count;
    const double rate = settings.rate;

    const Codegen::IdlTypeLibrary library(idlFolders(options));
    const Codegen::CdrCodec codec(library.model());
    const QString type = portType(codec, port, where);
    const bool json = options.has(QStringLiteral("--json"));

    const InterruptScope interrupts;
    PortTap tap(port, settings.connector, where);
    qint64 printed = 0;
    QElapsedTimer sincePrinted;
    while (!s_interrupted && (count == 0 || printed < count)) {
        const std::optional<PortSample> sample = tap.next(100);
        if (!sample)
            continue;
        if (rate > 0 && sincePrinted.isValid() && sincePrinted.elapsed() < 1000.0 / rate)
            continue;
        QString problem;
        const QJsonValue value = codec.decode(type, sample->cdr, tap.littleEndian(), &problem);
        if (!problem.isEmpty()) {
            report(QStringLiteral("%1: a sample of %2 bytes is no %3: %4")
                       .arg(where).arg(sample->cdr.size()).arg(type, problem),
                   streams);
            continue;
        }
        streams.out << (json ? codec.toJson(type, value) : codec.toText(type, value)) << '\n';
        streams.out.flush();
        sincePrinted.start();
        ++printed;
    }
    tap.close();
    if (tap.dropped() > 0)
        report(QStringLiteral("%1 sample(s) were dropped: they came faster than they could be printed")
                   .arg(tap.dropped()),
               streams);
    return ExitOk;
}

int RtDataCommand::inject(const RtOptions &options, const PortInfo &port, const QString &where,
                          Streams streams)
{
    DataSettings settings;
    if (const QString error = parseSettings(options, 1, &settings); !error.isEmpty())
        return usageError(error, streams);
    if (settings.count < 1)
        return usageError(QStringLiteral("-n needs a number of times"), streams);
    const qint64 times = settings.count;
    const double rate = settings.rate;

    // Every value is checked before anything is written.
    QStringList texts = options.positionals.mid(1);
    QStringList origins;
    for (int i = 0; i < texts.size(); ++i)
        origins.append(QStringLiteral("value %1").arg(i + 1));
    const QString from = options.value(QStringLiteral("--from"));
    if (!from.isEmpty()) {
        QFile file;
        openInput(from, &file);
        int line = 0;
        while (!file.atEnd()) {
            ++line;
            const QString text = QString::fromUtf8(file.readLine()).trimmed();
            if (text.isEmpty() || text.startsWith(QLatin1Char('#')))
                continue;
            texts.append(text);
            origins.append(QStringLiteral("%1:%2").arg(from).arg(line));
        }
    }
    if (texts.isEmpty())
        return usageError(QStringLiteral("inject needs at least one VALUE or --from FILE"), streams);

    const Codegen::IdlTypeLibrary library(idlFolders(options));
    const Codegen::CdrCodec codec(library.model());
    const QString type = portType(codec, port, where);
    QList<QJsonValue> values;
    for (int i = 0; i < texts.size(); ++i) {
        QString problem;
        const QJsonValue value = codec.parseArgument(type, texts.at(i), &problem);
        if (problem.isEmpty())
            codec.encode(type, value, true, &problem);
        if (!problem.isEmpty())
            throw Error(Error::Kind::BadPath,
                        QStringLiteral("%1: %2 for %3: %4").arg(where, origins.at(i), type, problem));
        values.append(value);
    }

    const InterruptScope interrupts;
    PortFeed feed(port, settings.connector, where);
    QElapsedTimer clock;
    clock.start();
    qint64 written = 0;
    for (qint64 round = 0; round < times && !s_interrupted; ++round) {
        for (const QJsonValue &value : std::as_const(values)) {
            if (s_interrupted)
                break;
            if (rate > 0) {
                const qint64 due = qint64(double(written) * 1000.0 / rate);
                while (clock.elapsed() < due && !s_interrupted)
                    QThread::msleep(ulong(std::min<qint64>(50, due - clock.elapsed())));
            }
            // Encoded when sent, so that a timed type's default timestamp is the sending time.
            feed.put(codec.encode(type, value, feed.littleEndian(), nullptr));
            ++written;
        }
    }
    linger(settings.linger);
    feed.close();
    return ExitOk;
}

int RtDataCommand::record(const RtOptions &options, Streams streams)
{
    DataSettings settings;
    if (const QString error = parseSettings(options, 0, &settings); !error.isEmpty())
        return usageError(error, streams);
    const qint64 count = settings.count;
    const double duration = settings.duration;

    const Codegen::IdlTypeLibrary library(idlFolders(options));
    const Codegen::CdrCodec codec(library.model());
    struct Recorded
    {
        QString where;
        QString type;
        std::unique_ptr<PortTap> tap;
    };
    std::vector<Recorded> ports;
    for (const QString &text : options.positionals) {
        const auto [found, where] = port(text);
        ports.push_back({where, portType(codec, found, where), nullptr});
        ports.back().tap = std::make_unique<PortTap>(found, settings.connector, where);
    }
    const QString target = options.value(QStringLiteral("-o"));
    QFile file;
    const bool opened = target == QLatin1String("-")
        ? file.open(stdout, QIODevice::WriteOnly)
        : (file.setFileName(target), file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    if (!opened)
        throw Error(Error::Kind::NotFound, QStringLiteral("%1: %2").arg(target, file.errorString()));

    const InterruptScope interrupts;
    QElapsedTimer clock;
    clock.start();
    qint64 written = 0;
    while (!s_interrupted && (count == 0 || written < count)
           && (duration == 0 || clock.elapsed() < qint64(duration * 1000))) {
        // What every port has now, written in the order it arrived.
        struct Arrived
        {
            PortSample sample;
            Recorded *port;
        };
        std::vector<Arrived> arrived;
        for (Recorded &recorded : ports) {
            while (std::optional<PortSample> sample = recorded.tap->next(0))
                arrived.push_back({std::move(*sample), &recorded});
        }
        const bool any = !arrived.empty();
        std::stable_sort(arrived.begin(), arrived.end(), [](const Arrived &a, const Arrived &b) {
            return a.sample.receivedMs < b.sample.receivedMs;
        });
        for (const Arrived &a : arrived) {
            if (count != 0 && written >= count)
                break;
            QString problem;
            const QJsonValue value = codec.decode(a.port->type, a.sample.cdr, a.port->tap->littleEndian(), &problem);
            if (!problem.isEmpty()) {
                report(QStringLiteral("%1: a sample is no %2: %3").arg(a.port->where, a.port->type, problem), streams);
                continue;
            }
            const QString line = QStringLiteral("{\"t\":%1,\"port\":%2,\"type\":%3,\"value\":%4}\n")
                                     .arg(a.sample.receivedMs)
                                     .arg(Codegen::CdrCodec::jsonText(a.port->where), Codegen::CdrCodec::jsonText(a.port->type),
                                          codec.toJson(a.port->type, value));
            if (file.write(line.toUtf8()) < 0)
                throw Error(Error::Kind::NotFound, QStringLiteral("%1: %2").arg(target, file.errorString()));
            ++written;
        }
        file.flush();
        if (!any)
            ports.front().tap->wait(20); // waits a little for the first port, then looks at all again
    }
    for (Recorded &recorded : ports)
        recorded.tap->close();
    report(QStringLiteral("%1 sample(s) recorded").arg(written), streams);
    return ExitOk;
}

int RtDataCommand::play(const RtOptions &options, Streams streams)
{
    DataSettings settings;
    if (const QString error = parseSettings(options, 0, &settings); !error.isEmpty())
        return usageError(error, streams);
    const double rate = settings.rate;

    // The whole recording is read and checked before anything is written.
    const QString source = options.value(QStringLiteral("--play"));
    QFile file;
    openInput(source, &file);
    struct Entry
    {
        qint64 t;
        int port;
        QJsonValue value;
    };
    std::vector<Entry> entries;
    QStringList recordedPorts;
    QStringList recordedTypes;
    int lineNumber = 0;
    while (!file.atEnd()) {
        ++lineNumber;
        const QByteArray line = file.readLine().trimmed();
        if (line.isEmpty())
            continue;
        QJsonParseError parseError;
        const QJsonObject object = QJsonDocument::fromJson(line, &parseError).object();
        const QString recordedPort = object.value(QStringLiteral("port")).toString();
        if (parseError.error != QJsonParseError::NoError || recordedPort.isEmpty()
            || !object.value(QStringLiteral("t")).isDouble())
            throw Error(Error::Kind::BadPath,
                        QStringLiteral("%1:%2: not a recorded sample (t, port, type, value)").arg(source).arg(lineNumber));
        qsizetype index = recordedPorts.indexOf(recordedPort);
        if (index < 0) {
            recordedPorts.append(recordedPort);
            recordedTypes.append(object.value(QStringLiteral("type")).toString());
            index = recordedPorts.size() - 1;
        }
        entries.push_back({object.value(QStringLiteral("t")).toInteger(), int(index), object.value(QStringLiteral("value"))});
    }
    if (recordedPorts.size() != options.positionals.size())
        throw Error(Error::Kind::BadPath,
                    QStringLiteral("%1 holds %2 port(s) (%3) but %4 PATH:PORT(s) were given")
                        .arg(source)
                        .arg(recordedPorts.size())
                        .arg(recordedPorts.join(QStringLiteral(", ")))
                        .arg(options.positionals.size()));

    const Codegen::IdlTypeLibrary library(idlFolders(options));
    const Codegen::CdrCodec codec(library.model());
    std::vector<std::pair<PortInfo, QString>> targets;
    for (qsizetype i = 0; i < recordedPorts.size(); ++i) {
        targets.push_back(port(options.positionals.at(i)));
        const QString type = portType(codec, targets.back().first, targets.back().second);
        if (type != recordedTypes.at(i))
            throw Error(Error::Kind::Incompatible,
                        QStringLiteral("%1 takes %2, but %3 was recorded with %4")
                            .arg(targets.back().second, type, recordedPorts.at(i), recordedTypes.at(i)));
    }
    for (const Entry &entry : entries) {
        QString problem;
        codec.encode(recordedTypes.at(entry.port), entry.value, true, &problem);
        if (!problem.isEmpty())
            throw Error(Error::Kind::BadPath, QStringLiteral("%1: a sample of %2: %3")
                                                  .arg(source, recordedPorts.at(entry.port), problem));
    }

    const InterruptScope interrupts;
    std::vector<std::unique_ptr<PortFeed>> feeds;
    for (const auto &[found, where] : targets)
        feeds.push_back(std::make_unique<PortFeed>(found, settings.connector, where));
    QElapsedTimer clock;
    clock.start();
    const qint64 start = entries.empty() ? 0 : entries.front().t;
    for (size_t i = 0; i < entries.size() && !s_interrupted; ++i) {
        const qint64 due = rate > 0 ? qint64(double(i) * 1000.0 / rate) : entries[i].t - start;
        while (clock.elapsed() < due && !s_interrupted)
            QThread::msleep(ulong(std::min<qint64>(50, due - clock.elapsed())));
        PortFeed &feed = *feeds[size_t(entries[i].port)];
        feed.put(codec.encode(recordedTypes.at(entries[i].port), entries[i].value, feed.littleEndian(), nullptr));
    }
    linger(settings.linger);
    for (auto &feed : feeds)
        feed->close();
    return ExitOk;
}

} // namespace Cli

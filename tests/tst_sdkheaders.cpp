// SPDX-License-Identifier: MIT
// Every public header OpenRTM-aist 2.1 installs exists in the component SDK, compiles alone in a
// translation unit as C++11 (the standard OpenRTP 2.0 projects build with), with the flags of the
// SDK's CMake package, and brings at least the standard and system headers OpenRTM-aist's header of
// the same name brings: user code that relied on those (std::cout after <rtm/Manager.h>, sleep()
// after <coil/OS.h>) compiles here as it did there; and the declarations application code uses
// resolve after including the header that declares them in OpenRTM-aist. Both lists are data
// (data/openrtm/headers.txt, data/openrtm/symbols.txt), written from OpenRTM-aist's install tree.
#include <QDir>
#include <QFile>
#include <QHash>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

namespace {

constexpr int configureTimeoutMs = 120 * 1000;
constexpr int compileTimeoutMs = 120 * 1000;

/// One public header: its name under the include root and what it brings in OpenRTM-aist.
struct HeaderFact
{
    QString name;
    QStringList brings;
};

/// A declaration OpenRTM-aist's header has: its kind (ns, member, value, macro) and its name.
struct SymbolFact
{
    QString kind;
    QString name;
};

/// What compiling a header alone, and with the probes of its declarations, gave.
struct CompileResult
{
    bool ok = false; ///< the header alone
    QString output;
    QSet<QString> included;
    bool symbolsOk = false; ///< the header and its probes
    QString symbolOutput;
};

QHash<QString, QList<SymbolFact>> readSymbolFacts(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QStringLiteral("cannot read %1").arg(path);
        return {};
    }
    static const QSet<QString> kinds{QStringLiteral("ns"), QStringLiteral("member"), QStringLiteral("value"),
                                     QStringLiteral("macro")};
    QHash<QString, QList<SymbolFact>> facts;
    int lineNumber = 0;
    while (!file.atEnd()) {
        ++lineNumber;
        const QString line = QString::fromUtf8(file.readLine()).trimmed();
        if (line.isEmpty() || line.startsWith('#'))
            continue;
        const QStringList fields = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (fields.size() != 3 || !kinds.contains(fields.at(1))) {
            *error = QStringLiteral("%1:%2: expected 'header kind name'").arg(path).arg(lineNumber);
            return {};
        }
        facts[fields.at(0)].append({fields.at(1), fields.at(2)});
    }
    return facts;
}

/**
 * A translation unit that includes @p header and names each declaration in a way that compiles
 * only when the name resolves: a using-declaration at namespace scope, a using-declaration in a
 * class derived from the member's class (inherited and protected members count), sizeof of an
 * enumerator, #error for a missing macro.
 */
QByteArray probeSource(const QString &header, const QList<SymbolFact> &symbols)
{
    QByteArray source = QStringLiteral("#include <%1>\n").arg(header).toUtf8();
    int index = 0;
    for (const SymbolFact &symbol : symbols) {
        const QByteArray name = symbol.name.toUtf8();
        const QByteArray id = QByteArray::number(++index);
        if (symbol.kind == QLatin1String("macro")) {
            source += "#ifndef " + name + "\n#error \"macro " + name + " is not defined\"\n#endif\n";
        } else if (symbol.kind == QLatin1String("ns")) {
            source += "namespace probe" + id + " { using ::" + name + "; }\n";
        } else if (symbol.kind == QLatin1String("value")) {
            source += "static_assert(sizeof(::" + name + ") > 0, \"" + name + "\");\n";
        } else {
            const int split = name.lastIndexOf("::");
            const QByteArray owner = name.left(split);
            source += "struct Probe" + id + " : ::" + owner + " { using ::" + name + "; };\n";
        }
    }
    return source;
}

QList<HeaderFact> readHeaderFacts(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QStringLiteral("cannot read %1").arg(path);
        return {};
    }
    QList<HeaderFact> facts;
    int lineNumber = 0;
    while (!file.atEnd()) {
        ++lineNumber;
        const QString line = QString::fromUtf8(file.readLine()).trimmed();
        if (line.isEmpty() || line.startsWith('#'))
            continue;
        const int colon = line.indexOf(':');
        if (colon <= 0) {
            *error = QStringLiteral("%1:%2: expected 'header: brings…'").arg(path).arg(lineNumber);
            return {};
        }
        facts.append({line.left(colon).trimmed(),
                      line.mid(colon + 1).split(QLatin1Char(' '), Qt::SkipEmptyParts)});
    }
    return facts;
}

/**
 * The name a translation unit would use for an included file, when it is a standard C++ header
 * or a C / POSIX header (`iostream`, `unistd.h`, `sys/types.h`); empty for anything else
 * (compiler internals, the ORB's and the SDK's own headers).
 */
QString publicSystemName(const QString &path)
{
    static const QRegularExpression cxx(QStringLiteral("/c\\+\\+/[0-9]+/([^/]+)$"));
    static const QRegularExpression c(
        QStringLiteral("^/usr/include/(?:[a-z0-9_]+-linux-gnu[a-z0-9_]*/)?((?:sys/|netinet/|arpa/)?[^/]+\\.h)$"));
    static const QSet<QString> internal{QStringLiteral("features.h"), QStringLiteral("features-time64.h"),
                                        QStringLiteral("stdc-predef.h")};
    const QString clean = QDir::cleanPath(path);
    QRegularExpressionMatch match = cxx.match(clean);
    if (match.hasMatch())
        return match.captured(1);
    match = c.match(clean);
    if (match.hasMatch() && !internal.contains(match.captured(1)))
        return match.captured(1);
    return QString();
}

QSet<QString> includedSystemHeaders(const QString &compilerOutput)
{
    // g++ -H prints one line per opened header: dots for the depth, a blank, the path.
    static const QRegularExpression line(QStringLiteral("^\\.+ (\\S+)$"), QRegularExpression::MultilineOption);
    QSet<QString> names;
    for (auto it = line.globalMatch(compilerOutput); it.hasNext();) {
        const QString name = publicSystemName(it.next().captured(1));
        if (!name.isEmpty())
            names.insert(name);
    }
    return names;
}

/// The compiler's messages without -H's include tree.
QString diagnostics(const QString &compilerOutput)
{
    QStringList lines;
    for (const QString &line : compilerOutput.split('\n'))
        if (!line.startsWith('.') && !line.startsWith(QLatin1String("Multiple include guards")))
            lines << line;
    return lines.join('\n').trimmed();
}

} // namespace

class TestSdkHeaders : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void everyHeaderIsListed();
    void headerCompilesAlone_data();
    void headerCompilesAlone();
    void headerBringsWhatOpenRtmBrings_data();
    void headerBringsWhatOpenRtmBrings();
    void declarationsResolve_data();
    void declarationsResolve();

private:
    QStringList packageFlags(QString *error);
    QHash<QString, QPair<bool, QString>> compile(const QString &folder, const QStringList &flags,
                                                 const QList<QPair<QString, QByteArray>> &sources);
    void compileAll(const QStringList &flags);

    QTemporaryDir m_work;
    QList<HeaderFact> m_facts;
    QHash<QString, QList<SymbolFact>> m_symbols;
    QHash<QString, CompileResult> m_results;
};

void TestSdkHeaders::initTestCase()
{
    QVERIFY(m_work.isValid());
    QString error;
    m_facts = readHeaderFacts(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/openrtm/headers.txt"), &error);
    QVERIFY2(!m_facts.isEmpty(), qPrintable(error));
    m_symbols = readSymbolFacts(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/openrtm/symbols.txt"), &error);
    QVERIFY2(!m_symbols.isEmpty(), qPrintable(error));
    const QStringList flags = packageFlags(&error);
    QVERIFY2(!flags.isEmpty(), qPrintable(error));
    compileAll(flags);
}

// The include directories and flags a project gets from find_package(OpenRTM) against the build
// tree's prefix, read by configuring a project that only prints them.
QStringList TestSdkHeaders::packageFlags(QString *error)
{
    const QString dir = m_work.filePath(QStringLiteral("probe"));
    QDir().mkpath(dir);
    QFile lists(dir + QStringLiteral("/CMakeLists.txt"));
    if (!lists.open(QIODevice::WriteOnly)) {
        *error = QStringLiteral("cannot write %1").arg(lists.fileName());
        return {};
    }
    lists.write("cmake_minimum_required(VERSION 3.16)\n"
                "project(probe NONE)\n"
                "find_package(OpenRTM REQUIRED)\n"
                "file(WRITE ${CMAKE_BINARY_DIR}/flags.txt \"${OPENRTM_CFLAGS}\\n${OPENRTM_INCLUDE_DIRS}\\n\")\n");
    lists.close();
    QProcess cmake;
    cmake.setProcessChannelMode(QProcess::MergedChannels);
    cmake.start(QStringLiteral(RTSTUDIO_CMAKE_COMMAND),
                {"-S", dir, "-B", dir + "/build", QStringLiteral("-DCMAKE_PREFIX_PATH=") + RTSTUDIO_BUILD_DIR});
    if (!cmake.waitForFinished(configureTimeoutMs) || cmake.exitCode() != 0) {
        *error = QStringLiteral("configuring a find_package(OpenRTM) project failed:\n%1")
                     .arg(QString::fromLocal8Bit(cmake.readAll()));
        return {};
    }
    QFile written(dir + QStringLiteral("/build/flags.txt"));
    if (!written.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QStringLiteral("the probe project wrote no flags");
        return {};
    }
    const QStringList lines = QString::fromUtf8(written.readAll()).split('\n');
    QStringList flags = lines.value(0).split(QRegularExpression(QStringLiteral("[ ;]+")), Qt::SkipEmptyParts);
    for (const QString &include : lines.value(1).split(';', Qt::SkipEmptyParts))
        flags << QStringLiteral("-I") + include;
    // -Wall as the package gives it, -O0 for speed; what OpenRTP 2.0 projects set last.
    flags.removeAll(QStringLiteral("-O2"));
    flags << QStringLiteral("-std=gnu++11");
    return flags;
}

// Compiles each source of @p sources (by key), as many at a time as there are cores: whether it
// compiled, and the compiler's output with -H's include tree. The sources are files of m_work's
// @p folder named by relative paths, so that ccache (when installed) finds the next run's
// compilations, made in another temporary folder, in its cache.
QHash<QString, QPair<bool, QString>> TestSdkHeaders::compile(const QString &folder, const QStringList &flags,
                                                            const QList<QPair<QString, QByteArray>> &sources)
{
    const QString dir = m_work.filePath(folder);
    QDir().mkpath(dir);
    const QString ccache = QStandardPaths::findExecutable(QStringLiteral("ccache"));
    const QString compiler = QStringLiteral(RTSTUDIO_CXX_COMPILER);
    const int parallel = qMax(1, QThread::idealThreadCount());
    QHash<QString, QPair<bool, QString>> results;
    QList<QPair<QString, QByteArray>> waiting = sources;
    QList<QPair<QString, QProcess *>> running;
    while (!waiting.isEmpty() || !running.isEmpty()) {
        while (!waiting.isEmpty() && running.size() < parallel) {
            const auto [key, source] = waiting.takeFirst();
            const QString file = QString(key).replace('/', '_') + QStringLiteral(".cpp");
            QFile written(dir + '/' + file);
            if (!written.open(QIODevice::WriteOnly) || written.write(source) != source.size()) {
                results.insert(key, {false, QStringLiteral("cannot write %1").arg(written.fileName())});
                continue;
            }
            written.close();
            auto *process = new QProcess(this);
            process->setProcessChannelMode(QProcess::MergedChannels);
            process->setWorkingDirectory(dir);
            const QStringList arguments = QStringList(flags) << "-fsyntax-only" << "-H" << file;
            if (ccache.isEmpty())
                process->start(compiler, arguments);
            else
                process->start(ccache, QStringList(compiler) << arguments);
            running.append({key, process});
        }
        if (running.isEmpty())
            continue;
        const auto [key, process] = running.takeFirst();
        const bool ok = process->waitForFinished(compileTimeoutMs) && process->exitStatus() == QProcess::NormalExit
                        && process->exitCode() == 0;
        if (process->state() != QProcess::NotRunning) {
            process->kill();
            process->waitForFinished();
        }
        results.insert(key, {ok, QString::fromLocal8Bit(process->readAll())});
        delete process;
    }
    return results;
}

// Each header with the probes of its declarations; the header alone only where that failed, to
// tell a header that does not compile from a declaration that is missing.
void TestSdkHeaders::compileAll(const QStringList &flags)
{
    QList<QPair<QString, QByteArray>> probes;
    for (const HeaderFact &fact : m_facts)
        probes.append({fact.name, probeSource(fact.name, m_symbols.value(fact.name))});
    const auto probed = compile(QStringLiteral("probes"), flags, probes);
    QList<QPair<QString, QByteArray>> alone;
    for (const HeaderFact &fact : m_facts)
        if (!probed.value(fact.name).first)
            alone.append({fact.name, probeSource(fact.name, {})});
    const auto aloneResults = compile(QStringLiteral("alone"), flags, alone);
    for (const HeaderFact &fact : m_facts) {
        const auto withProbes = probed.value(fact.name);
        const auto plain = withProbes.first ? withProbes : aloneResults.value(fact.name);
        CompileResult result;
        result.ok = plain.first;
        result.output = diagnostics(plain.second);
        result.included = includedSystemHeaders(plain.second);
        result.symbolsOk = withProbes.first;
        result.symbolOutput = diagnostics(withProbes.second);
        m_results.insert(fact.name, result);
    }
}

void TestSdkHeaders::everyHeaderIsListed()
{
    // The list covers the three trees OpenRTM-aist installs, and the IDL wrappers.
    QSet<QString> roots;
    for (const HeaderFact &fact : m_facts)
        roots.insert(fact.name.section('/', 0, fact.name.startsWith(QLatin1String("rtm/idl/")) ? 1 : 0));
    QVERIFY(roots.contains(QStringLiteral("rtm")));
    QVERIFY(roots.contains(QStringLiteral("rtm/idl")));
    QVERIFY(roots.contains(QStringLiteral("coil")));
    QVERIFY(roots.contains(QStringLiteral("hrtm")));
    QVERIFY(m_facts.size() >= 150);
}

void TestSdkHeaders::headerCompilesAlone_data()
{
    QTest::addColumn<QString>("header");
    for (const HeaderFact &fact : m_facts)
        QTest::newRow(qPrintable(fact.name)) << fact.name;
}

void TestSdkHeaders::headerCompilesAlone()
{
    QFETCH(QString, header);
    const CompileResult result = m_results.value(header);
    QVERIFY2(result.ok, qPrintable(QStringLiteral("#include <%1> alone does not compile:\n%2")
                                       .arg(header, result.output.left(4000))));
}

void TestSdkHeaders::headerBringsWhatOpenRtmBrings_data()
{
    QTest::addColumn<QString>("header");
    QTest::addColumn<QStringList>("brings");
    for (const HeaderFact &fact : m_facts)
        QTest::newRow(qPrintable(fact.name)) << fact.name << fact.brings;
}

void TestSdkHeaders::headerBringsWhatOpenRtmBrings()
{
    QFETCH(QString, header);
    QFETCH(QStringList, brings);
    const CompileResult result = m_results.value(header);
    if (!result.ok)
        QFAIL(qPrintable(QStringLiteral("%1 does not compile (see headerCompilesAlone)").arg(header)));
    QStringList missing;
    for (const QString &name : brings)
        if (!result.included.contains(name))
            missing << name;
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("<%1> does not bring what OpenRTM-aist's brings: %2")
                                               .arg(header, missing.join(' '))));
}

void TestSdkHeaders::declarationsResolve_data()
{
    QTest::addColumn<QString>("header");
    QTest::addColumn<int>("count");
    int total = 0;
    for (const HeaderFact &fact : m_facts) {
        const int count = m_symbols.value(fact.name).size();
        total += count;
        if (count > 0)
            QTest::newRow(qPrintable(fact.name)) << fact.name << count;
    }
    // Every declaration belongs to a listed header.
    int listed = 0;
    for (const auto &symbols : qAsConst(m_symbols))
        listed += symbols.size();
    QCOMPARE(total, listed);
}

void TestSdkHeaders::declarationsResolve()
{
    QFETCH(QString, header);
    QFETCH(int, count);
    const CompileResult result = m_results.value(header);
    if (!result.ok)
        QFAIL(qPrintable(QStringLiteral("%1 does not compile (see headerCompilesAlone)").arg(header)));
    QVERIFY2(result.symbolsOk, qPrintable(QStringLiteral("of the %1 declarations of <%2>, some do not resolve:\n%3")
                                              .arg(count)
                                              .arg(header, result.symbolOutput.left(6000))));
}

QTEST_GUILESS_MAIN(TestSdkHeaders)
#include "tst_sdkheaders.moc"

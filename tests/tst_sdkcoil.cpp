// SPDX-License-Identifier: MIT
// coil, the utility library of the component SDK: the OpenRTM-aist behaviour components rely on.
#include <coil/Affinity.h>
#include <coil/Async.h>
#include <coil/ClockManager.h>
#include <coil/Condition.h>
#include <coil/DynamicLib.h>
#include <coil/Factory.h>
#include <coil/File.h>
#include <coil/Guard.h>
#include <coil/Logger.h>
#include <coil/Mutex.h>
#include <coil/NonCopyable.h>
#include <coil/OS.h>
#include <coil/PeriodicTask.h>
#include <coil/Process.h>
#include <coil/Properties.h>
#include <coil/Routing.h>
#include <coil/SharedMemory.h>
#include <coil/Signal.h>
#include <coil/Singleton.h>
#include <coil/Task.h>
#include <coil/Time.h>
#include <coil/TimeMeasure.h>
#include <coil/TimeValue.h>
#include <coil/Timer.h>
#include <coil/UUID.h>
#include <coil/crc.h>
#include <coil/stringutil.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <atomic>
#include <deque>
#include <memory>
#include <sstream>
#include <thread>
#include <vector>

// The vector extraction OpenRTM-aist's ConfigSample (and OpenRTP's generated VectorConvert.h of
// that generation) declares after coil's headers: a template in namespace std that splits at
// commas and converts each element with coil::stringTo. coil itself has none.
namespace std {
template<typename T> std::istream &operator>>(std::istream &is, std::vector<T> &v)
{
    std::string s;
    is >> s;
    const coil::vstring sv = coil::split(s, ",");
    v.resize(sv.size());
    for (size_t i = 0; i < sv.size(); ++i) {
        T tv;
        if (coil::stringTo(tv, sv[i].c_str()))
            v[i] = tv;
    }
    return is;
}
} // namespace std

// The other published style: the same kind of operator in the global namespace, declared after
// coil/stringutil.h (RT Studio's template and hrpsys put it there). A deque stands in for the
// container so that both operators can live in this file.
template<typename T> std::istream &operator>>(std::istream &is, std::deque<T> &v)
{
    std::string s;
    std::getline(is, s);
    v.clear();
    for (const std::string &item : coil::split(s, ",")) {
        T tv;
        if (!coil::stringTo(tv, item.c_str())) {
            is.setstate(std::ios::failbit);
            return is;
        }
        v.push_back(tv);
    }
    return is;
}

Q_DECLARE_METATYPE(coil::vstring)

namespace {

const char *const kSpec[] = {
    "implementation_id",
    "ConsoleIn",
    "type_name",
    "ConsoleIn",
    "max_instance",
    "1",
    "conf.default.gain",
    "1.5",
    "conf.default.name",
    "  padded  ",
    "conf.mode1.gain",
    "2.0",
    "",
};

std::string storeText(coil::Properties &prop)
{
    std::ostringstream out;
    prop.list(out);
    return out.str();
}

class Counter : public coil::Singleton<Counter>
{
public:
    std::atomic<int> hits {0};

private:
    friend class coil::Singleton<Counter>;
    Counter() { ++constructed; }

public:
    static std::atomic<int> constructed;
};
std::atomic<int> Counter::constructed {0};

class RecordingTask : public coil::Task
{
public:
    int svc() override
    {
        svcThread = std::this_thread::get_id();
        ++runs;
        return 0;
    }
    void finalize() override
    {
        ++finalized;
        coil::Task::finalize();
    }
    std::thread::id svcThread;
    std::atomic<int> runs {0};
    std::atomic<int> finalized {0};
};

// Plug-in style classes for the factory tests.
class Shape
{
public:
    virtual ~Shape() = default;
    virtual int corners() const = 0;
};
class Triangle : public Shape
{
public:
    int corners() const override { return 3; }
};
class Square : public Shape
{
public:
    int corners() const override { return 4; }
};

// A log destination that keeps the lines it receives.
class MemoryLogBuffer : public coil::LogStreamBuffer
{
public:
    explicit MemoryLogBuffer(int *destroyed = nullptr)
        : m_destroyed(destroyed)
    { }
    ~MemoryLogBuffer() override
    {
        if (m_destroyed)
            ++*m_destroyed;
    }
    void write(int level, const std::string &name, const std::string &, const std::string &mes) override
    {
        lines.push_back(std::to_string(level) + " " + name + ": " + mes);
    }
    void flush() override { ++flushes; }
    std::vector<std::string> lines;
    int flushes = 0;

private:
    int *m_destroyed;
};

// The smallest LogStream: lines go to the buffer under a fixed name.
class NamedLogStream : public coil::LogStream
{
public:
    NamedLogStream(coil::LogStreamBuffer *buffer, int level)
        : coil::LogStream(buffer, 0, 8, level)
    { }
    ~NamedLogStream() override = default;
    void write(int level, const std::string &mes) override
    {
        if (isValid(level))
            ostream_type->write(level, "test", "now", mes);
    }
};

} // namespace

class TestSdkCoil : public QObject
{
    Q_OBJECT

private slots:
    // Properties
    void specArrayBuildsDefaultTree();
    void specArrayStopsAtCount();
    void valuesOverrideDefaults();
    void nodeTree();
    void writeAccessCreatesNodes();
    void copiesAreDeep();
    void mergeOperator();
    void load_data();
    void load();
    void loadMalformedTextDoesNotCrash_data();
    void loadMalformedTextDoesNotCrash();
    void loadRandomTextRoundTrips();
    void storeRoundTrip();
    void streamDump();
    void mapConstructor();

    // stringutil
    void split_data();
    void split();
    void toBool_data();
    void toBool();
    void trimming();
    void escapeRoundTrip();
    void replaceString();
    void stringToNumbers_data();
    void stringToNumbers();
    void stringToBool_data();
    void stringToBool();
    void stringToStringKeepsBlanks();
    void stringToDurations();
    void stringToVectorViaNamespaceStdOperator();
    void stringToContainerViaGlobalOperator();
    void otosAndSprintf();
    void addressChecks();
    void listHelpers();
    void argvHelpers();
    void getlinePortableLineEnds();

    // time, threads, OS
    void timeValueNormalises_data();
    void timeValueNormalises();
    void timeValueFromDouble_data();
    void timeValueFromDouble();
    void timeValueArithmetic();
    void timeFunctions();
    void mutexAndGuard();
    void conditionTimesOut();
    void singletonCreatesOnce();
    void taskRunsSvcInThread();
    void timeMeasure();
    void osWrappers();
    void getOpt();
    void uuid();
    void clocks();
    void files();
    void dynamicLib();
    void nonCopyable();
    void asyncInvoker();
    void periodicTask();
    void periodicTaskStopsWithoutWaitingForThePeriod();
    void checksums_data();
    void checksums();
    void processes();
    void signalAction();
    void timerCallsAtTheirInterval();
    void timerTasksMayAddTasks();
    void factory();
    void globalFactoryIsShared();
    void logStreamLevels();
    void logStreamBufferFansOut();
    void threadAffinity();
    void sharedMemory();
    void sharedMemoryMissingName();
    void routingToLoopback();
    void deleteAsyncThread();
};

// ---------------------------------------------------------------- Properties

void TestSdkCoil::specArrayBuildsDefaultTree()
{
    coil::Properties prop(kSpec);
    QCOMPARE(prop.getProperty("implementation_id"), std::string("ConsoleIn"));
    QCOMPARE(prop.getProperty("conf.default.gain"), std::string("1.5"));
    QCOMPARE(prop.getProperty("conf.default.name"), std::string("padded"));
    QCOMPARE(prop.getDefault("conf.default.gain"), std::string("1.5"));

    const coil::Properties *conf = prop.findNode("conf");
    QVERIFY(conf);
    QCOMPARE(conf->getLeaf().size(), size_t(2)); // default, mode1
    coil::Properties &def = prop.getNode("conf.default");
    QCOMPARE(std::string(def.getName()), std::string("default"));
    QCOMPARE(def.getRoot(), conf);
    QCOMPARE(def.getProperty("gain"), std::string("1.5"));
    QCOMPARE(def.propertyNames(), (coil::vstring {"gain", "name"}));
    QCOMPARE(prop.size(), size_t(6));
    QVERIFY(!prop.findNode("conf.nothing"));
    QVERIFY(!prop.findNode(""));
    QCOMPARE(prop.getProperty("conf.nothing"), std::string());
}

void TestSdkCoil::specArrayStopsAtCount()
{
    coil::Properties prop(kSpec, 4);
    QCOMPARE(prop.propertyNames(), (coil::vstring {"implementation_id", "type_name"}));

    const char *const empty[] = {""};
    QCOMPARE(coil::Properties(empty).size(), size_t(0));
}

void TestSdkCoil::valuesOverrideDefaults()
{
    coil::Properties prop(kSpec);
    QCOMPARE(prop.setProperty("conf.default.gain", "3"), std::string());
    QCOMPARE(prop.getProperty("conf.default.gain"), std::string("3"));
    QCOMPARE(prop.getDefault("conf.default.gain"), std::string("1.5"));
    QCOMPARE(prop.setProperty("conf.default.gain", "4"), std::string("3"));

    // An explicitly set empty value wins over the default; the two-argument form falls back.
    prop.setProperty("max_instance", "");
    QCOMPARE(prop.getProperty("max_instance"), std::string());
    QCOMPARE(prop.getProperty("max_instance", "9"), std::string("9"));
    QCOMPARE(prop.getProperty("implementation_id", "x"), std::string("ConsoleIn"));

    prop.setDefault("exec_cxt.periodic.rate", "1000");
    QCOMPARE(prop.getProperty("exec_cxt.periodic.rate"), std::string("1000"));
    QCOMPARE(std::string(prop.findNode("exec_cxt.periodic.rate")->getDefaultValue()),
             std::string("1000"));

    // Blank keys are ignored.
    QCOMPARE(prop.setProperty("  ", "x"), std::string());
    QCOMPARE(prop.size(), size_t(7));
}

void TestSdkCoil::nodeTree()
{
    coil::Properties prop;
    QVERIFY(prop.createNode("a.b.c"));
    QVERIFY(!prop.createNode("a.b.c"));
    QVERIFY(!prop.createNode(""));
    QVERIFY(prop.hasKey("a"));
    QVERIFY(!prop.hasKey("b"));
    QVERIFY(prop.findNode("a")->hasKey("b"));

    coil::Properties &made = prop.getNode("x.y");
    QCOMPARE(std::string(made.getName()), std::string("y"));
    QCOMPARE(&prop.getNode("x.y"), &made);
    QCOMPARE(&prop.getNode(""), &prop);

    // An escaped dot stays inside one name.
    prop.setProperty("host\\.name.port", "80");
    QVERIFY(prop.hasKey("host\\.name"));

    coil::Properties *removed = prop.getNode("a").removeNode("b");
    QVERIFY(removed);
    QVERIFY(!removed->getRoot());
    QVERIFY(!prop.findNode("a.b"));
    QCOMPARE(removed->getProperty("c"), std::string());
    QVERIFY(removed->findNode("c"));
    delete removed;
    QVERIFY(!prop.getNode("a").removeNode("nothing"));

    // Deleting a child unlinks it from its parent.
    delete prop.findNode("x.y");
    QVERIFY(!prop.findNode("x.y"));
    QVERIFY(prop.findNode("x"));

    prop.clear();
    QCOMPARE(prop.size(), size_t(0));
    QVERIFY(prop.getLeaf().empty());
}

void TestSdkCoil::writeAccessCreatesNodes()
{
    coil::Properties prop(kSpec);
    prop["conf.default.gain"] += "0";
    QCOMPARE(prop.getProperty("conf.default.gain"), std::string("1.50"));
    prop["new.key"] = "v";
    QCOMPARE(prop.getProperty("new.key"), std::string("v"));

    const coil::Properties &constProp = prop;
    QCOMPARE(constProp["new.key"], std::string("v"));
    QCOMPARE(constProp["absent.key"], std::string());
    QVERIFY(!prop.findNode("absent.key"));
}

void TestSdkCoil::copiesAreDeep()
{
    coil::Properties prop(kSpec);
    prop.setProperty("conf", "own value of an inner node");
    coil::Properties copy(prop);
    copy.setProperty("conf.default.gain", "9");
    QCOMPARE(prop.getProperty("conf.default.gain"), std::string("1.5"));
    QCOMPARE(copy.getProperty("conf"), std::string("own value of an inner node"));
    QCOMPARE(copy.getDefault("conf.default.gain"), std::string("1.5"));

    coil::Properties assigned("other", "x");
    assigned = copy;
    QCOMPARE(assigned.getProperty("conf.default.gain"), std::string("9"));
    QCOMPARE(assigned.propertyNames(), copy.propertyNames());

    // Assigning a node of a tree replaces its content and keeps it findable.
    coil::Properties &node = prop.getNode("conf.mode1");
    node = coil::Properties(kSpec).getNode("conf.default");
    QCOMPARE(prop.getProperty("conf.mode1.gain"), std::string("1.5"));
    QCOMPARE(prop.getProperty("conf.mode1.name"), std::string("padded"));

    // Assigning a subtree to its own ancestor.
    coil::Properties tree(kSpec);
    tree = *tree.findNode("conf");
    QCOMPARE(tree.getProperty("default.gain"), std::string("1.5"));
}

void TestSdkCoil::mergeOperator()
{
    coil::Properties base(kSpec);
    coil::Properties extra;
    extra.setProperty("conf.default.gain", "7");
    extra.setProperty("vendor", "AIST");
    base << extra;
    QCOMPARE(base.getProperty("conf.default.gain"), std::string("7"));
    QCOMPARE(base.getProperty("vendor"), std::string("AIST"));
    QCOMPARE(base.getProperty("type_name"), std::string("ConsoleIn"));
    base << base;
    QCOMPARE(base.getProperty("vendor"), std::string("AIST"));
}

void TestSdkCoil::load_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QByteArray>("key");
    QTest::addColumn<QByteArray>("value");

    QTest::newRow("colon") << QByteArray("corba.nameservers: localhost:2809\n")
                           << QByteArray("corba.nameservers") << QByteArray("localhost:2809");
    QTest::newRow("equals") << QByteArray("logger.enable = YES\n") << QByteArray("logger.enable")
                            << QByteArray("YES");
    QTest::newRow("blank separator")
        << QByteArray("naming.type corba\n") << QByteArray("naming.type") << QByteArray("corba");
    QTest::newRow("blanks around")
        << QByteArray("   a.b   :   c d   \n") << QByteArray("a.b") << QByteArray("c d");
    QTest::newRow("hash comment") << QByteArray("# a: 1\na: 2\n") << QByteArray("a")
                                  << QByteArray("2");
    QTest::newRow("bang comment") << QByteArray("  ! a: 1\n") << QByteArray("a") << QByteArray();
    QTest::newRow("continuation") << QByteArray(
        "manager.modules.preload: A.so,\\\n    B.so,\\\n    C.so\nnext: 1\n")
                                  << QByteArray("manager.modules.preload")
                                  << QByteArray("A.so,B.so,C.so");
    QTest::newRow("comment and blank line inside continuation")
        << QByteArray("list: a,\\\n# b,\\\n\n  c\n") << QByteArray("list") << QByteArray("a,c");
    QTest::newRow("after continuation")
        << QByteArray("x: a\\\n b\nnext: 1\n") << QByteArray("next") << QByteArray("1");
    QTest::newRow("escaped backslash ends line")
        << QByteArray("path: C:\\\\\nnext: 1\n") << QByteArray("path") << QByteArray("C:\\");
    QTest::newRow("escaped separator in key")
        << QByteArray("a\\:b: c\n") << QByteArray("a:b") << QByteArray("c");
    QTest::newRow("escape sequences")
        << QByteArray("t: x\\ty\n") << QByteArray("t") << QByteArray("x\ty");
    QTest::newRow("crlf") << QByteArray("a: 1\r\nb: 2\r\n") << QByteArray("b") << QByteArray("2");
    QTest::newRow("cr only") << QByteArray("a: 1\rb: 2\r") << QByteArray("b") << QByteArray("2");
    QTest::newRow("no newline at end") << QByteArray("a: 1") << QByteArray("a") << QByteArray("1");
    QTest::newRow("continuation at end")
        << QByteArray("a: 1\\") << QByteArray("a") << QByteArray("1");
    QTest::newRow("key only") << QByteArray("flag\n") << QByteArray("flag") << QByteArray();
    QTest::newRow("later wins") << QByteArray("a: 1\na: 2\n") << QByteArray("a") << QByteArray("2");
}

void TestSdkCoil::load()
{
    QFETCH(QByteArray, text);
    QFETCH(QByteArray, key);
    QFETCH(QByteArray, value);

    std::istringstream in(text.toStdString());
    coil::Properties prop;
    prop.load(in);
    QCOMPARE(QByteArray::fromStdString(prop.getProperty(key.toStdString())), value);
}

void TestSdkCoil::loadMalformedTextDoesNotCrash_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::newRow("separators only") << QByteArray(":::: ===\n=\n:\n");
    QTest::newRow("dots") << QByteArray(".\n..: x\na..b: c\n.a: 1\na.: 2\n");
    QTest::newRow("backslashes") << QByteArray("\\\n\\\\\n\\:\n\\\\\\\n");
    QTest::newRow("binary") << QByteArray("\0\x01\xff: \xfe\n", 7);
    QTest::newRow("blank lines") << QByteArray("\n\n   \n\t\n");
    QTest::newRow("empty") << QByteArray();
}

void TestSdkCoil::loadMalformedTextDoesNotCrash()
{
    QFETCH(QByteArray, text);
    std::istringstream in(text.toStdString());
    coil::Properties prop;
    prop.load(in);
    // Whatever was read must survive a store/load cycle and a dump.
    const std::string stored = storeText(prop);
    std::istringstream again(stored);
    coil::Properties reread;
    reread.load(again);
    std::ostringstream dump;
    dump << prop;
    QCOMPARE(storeText(reread), stored);
}

void TestSdkCoil::loadRandomTextRoundTrips()
{
    // Text made of the characters the parser cares about: whatever it reads must be stored so
    // that reading it back gives the same tree.
    static const char alphabet[] = ":=\\.#! \t\n\rab";
    QRandomGenerator random(20240613);
    for (int round = 0; round < 2000; ++round) {
        std::string text;
        const int length = random.bounded(40);
        for (int i = 0; i < length; ++i)
            text += alphabet[random.bounded(int(sizeof(alphabet) - 1))];
        std::istringstream in(text);
        coil::Properties prop;
        prop.load(in);
        const std::string stored = storeText(prop);
        std::istringstream again(stored);
        coil::Properties reread;
        reread.load(again);
        QVERIFY2(storeText(reread) == stored,
                 qPrintable(QStringLiteral("input %1 stored as %2 re-stored as %3")
                                .arg(QString::fromStdString(coil::escape(text)),
                                     QString::fromStdString(coil::escape(stored)),
                                     QString::fromStdString(coil::escape(storeText(reread))))));
    }
}

void TestSdkCoil::storeRoundTrip()
{
    coil::Properties prop(kSpec);
    prop.setProperty("conf.default.gain", "2.5");
    prop.setProperty("text", "tab\there\nnewline\\backslash");
    prop.setProperty("corba.endpoints", "host:2810");

    // Only set values are written; defaults are not.
    const std::string listed = storeText(prop);
    QVERIFY(listed.find("conf.default.gain: 2.5\n") != std::string::npos);
    QVERIFY(listed.find("implementation_id") == std::string::npos);
    QVERIFY(listed.find("text: tab\\there\\nnewline\\\\backslash\n") != std::string::npos);

    std::ostringstream stored;
    prop.store(stored, "saved by the test");
    QCOMPARE(stored.str().substr(0, 20), std::string("# saved by the test\n"));

    std::istringstream in(stored.str());
    coil::Properties reread;
    reread.load(in);
    QCOMPARE(reread.getProperty("text"), prop.getProperty("text"));
    QCOMPARE(reread.getProperty("corba.endpoints"), std::string("host:2810"));
    QCOMPARE(reread.getProperty("conf.default.gain"), std::string("2.5"));
    QCOMPARE(reread.size(), size_t(3));
}

void TestSdkCoil::streamDump()
{
    coil::Properties prop(kSpec);
    std::ostringstream out;
    out << prop;
    const std::string dump = out.str();
    QVERIFY2(dump.find("- conf\n  - default\n    - gain: 1.5\n") != std::string::npos,
             dump.c_str());
    QVERIFY(dump.find("- implementation_id: ConsoleIn\n") != std::string::npos);

    const std::vector<std::string> lines = prop;
    QCOMPARE(lines.front(), std::string("- implementation_id: ConsoleIn"));
    QVERIFY(std::find(lines.begin(), lines.end(), "    - gain: 2.0") != lines.end());
}

void TestSdkCoil::mapConstructor()
{
    std::map<std::string, std::string> defaults {{"a.b", "1"}, {"c", "2"}};
    coil::Properties prop(defaults);
    QCOMPARE(prop.getProperty("a.b"), std::string("1"));
    QCOMPARE(prop.getDefault("c"), std::string("2"));
    QCOMPARE(prop.size(), size_t(2));
}

// ---------------------------------------------------------------- stringutil

void TestSdkCoil::split_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("delimiter");
    QTest::addColumn<bool>("ignoreEmpty");
    QTest::addColumn<coil::vstring>("expected");

    QTest::newRow("commas") << "a,b,c"
                            << "," << false << coil::vstring {"a", "b", "c"};
    QTest::newRow("blanks trimmed") << " a , b\t,c "
                                    << "," << false << coil::vstring {"a", "b", "c"};
    QTest::newRow("empty kept") << "a,,b,"
                                << "," << false << coil::vstring {"a", "", "b", ""};
    QTest::newRow("empty dropped") << "a,,b,"
                                   << "," << true << coil::vstring {"a", "b"};
    QTest::newRow("long delimiter") << "a::b::c"
                                    << "::" << false << coil::vstring {"a", "b", "c"};
    QTest::newRow("no delimiter found") << " abc "
                                        << "," << false << coil::vstring {"abc"};
    QTest::newRow("empty input") << ""
                                 << "," << false << coil::vstring {};
    QTest::newRow("empty delimiter") << " a,b "
                                     << "" << false << coil::vstring {"a,b"};
}

void TestSdkCoil::split()
{
    QFETCH(QString, input);
    QFETCH(QString, delimiter);
    QFETCH(bool, ignoreEmpty);
    QFETCH(coil::vstring, expected);
    QCOMPARE(coil::split(input.toStdString(), delimiter.toStdString(), ignoreEmpty), expected);
}

void TestSdkCoil::toBool_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("defaultValue");
    QTest::addColumn<bool>("expected");

    QTest::newRow("yes") << "YES" << false << true;
    QTest::newRow("yes lower") << "yes" << false << true;
    QTest::newRow("no") << "No" << true << false;
    QTest::newRow("other, default true") << "maybe" << true << true;
    QTest::newRow("other, default false") << "maybe" << false << false;
}

void TestSdkCoil::toBool()
{
    QFETCH(QString, text);
    QFETCH(bool, defaultValue);
    QFETCH(bool, expected);
    QCOMPARE(coil::toBool(text.toStdString(), "YES", "NO", defaultValue), expected);
}

void TestSdkCoil::trimming()
{
    QCOMPARE(coil::normalize("  MiXed Case\t"), std::string("mixed case"));
    QCOMPARE(coil::eraseBlank(" a b\tc "), std::string("abc"));
    QCOMPARE(coil::eraseHeadBlank(" \t a "), std::string("a "));
    QCOMPARE(coil::eraseTailBlank(" a \t "), std::string(" a"));
    QCOMPARE(coil::eraseBothEndsBlank("   "), std::string());
    QCOMPARE(coil::eraseBothEnds(" x "), std::string("x"));
    QCOMPARE(coil::toUpper("abC1"), std::string("ABC1"));
    QCOMPARE(coil::toLower("ABc1"), std::string("abc1"));
}

void TestSdkCoil::escapeRoundTrip()
{
    const std::string raw = "a\tb\nc\rd\fe\\f";
    const std::string escaped = coil::escape(raw);
    QCOMPARE(escaped, std::string("a\\tb\\nc\\rd\\fe\\\\f"));
    QCOMPARE(coil::unescape(escaped), raw);
    QCOMPARE(coil::unescape("\\q\\\"\\"), std::string("q\""));
    QVERIFY(coil::isEscaped("a\\:", 2));
    QVERIFY(!coil::isEscaped("a\\\\:", 3));
    QVERIFY(!coil::isEscaped(":", 0));
}

void TestSdkCoil::replaceString()
{
    QCOMPARE(coil::replaceString("a.b.c", ".", "::"), std::string("a::b::c"));
    QCOMPARE(coil::replaceString("aaa", "a", "aa"), std::string("aaaaaa"));
    QCOMPARE(coil::replaceString("abc", "", "x"), std::string("abc"));
}

void TestSdkCoil::stringToNumbers_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<double>("expected");

    QTest::newRow("integer") << QByteArray("42") << true << 42.0;
    QTest::newRow("negative") << QByteArray("-7") << true << -7.0;
    QTest::newRow("decimal") << QByteArray("0.25") << true << 0.25;
    QTest::newRow("exponent") << QByteArray("1e3") << true << 1000.0;
    QTest::newRow("leading blanks") << QByteArray("  8") << true << 8.0;
    QTest::newRow("letters") << QByteArray("abc") << false << 0.0;
    QTest::newRow("empty") << QByteArray("") << false << 0.0;
    QTest::newRow("blank") << QByteArray("   ") << false << 0.0;
}

void TestSdkCoil::stringToNumbers()
{
    QFETCH(QByteArray, text);
    QFETCH(bool, ok);
    QFETCH(double, expected);

    double d = -1.0;
    QCOMPARE(coil::stringTo(d, text.constData()), ok);
    QCOMPARE(d, ok ? expected : -1.0); // a failed conversion leaves the variable alone

    long l = -1;
    const bool integral = ok && expected == static_cast<long>(expected) && !text.contains('e')
        && !text.contains('.');
    if (integral) {
        QVERIFY(coil::stringTo(l, text.constData()));
        QCOMPARE(l, static_cast<long>(expected));
    } else if (!ok) {
        QVERIFY(!coil::stringTo(l, text.constData()));
        QCOMPARE(l, -1L);
    }

    int i = 5;
    QVERIFY(!coil::stringTo(i, nullptr));
    QCOMPARE(i, 5);
}

void TestSdkCoil::stringToBool_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<bool>("expected");

    QTest::newRow("true") << QByteArray("true") << true << true;
    QTest::newRow("TRUE blanks") << QByteArray(" TRUE ") << true << true;
    QTest::newRow("1") << QByteArray("1") << true << true;
    QTest::newRow("yes") << QByteArray("Yes") << true << true;
    QTest::newRow("on") << QByteArray("on") << true << true;
    QTest::newRow("false") << QByteArray("False") << true << false;
    QTest::newRow("0") << QByteArray("0") << true << false;
    QTest::newRow("no") << QByteArray("NO") << true << false;
    QTest::newRow("off") << QByteArray("off") << true << false;
    QTest::newRow("other") << QByteArray("2") << false << false;
    QTest::newRow("empty") << QByteArray("") << false << false;
}

void TestSdkCoil::stringToBool()
{
    QFETCH(QByteArray, text);
    QFETCH(bool, ok);
    QFETCH(bool, expected);
    for (bool initial : {false, true}) {
        bool value = initial;
        QCOMPARE(coil::stringTo(value, text.constData()), ok);
        QCOMPARE(value, ok ? expected : initial);
    }
}

void TestSdkCoil::stringToStringKeepsBlanks()
{
    std::string s = "old";
    QVERIFY(coil::stringTo(s, "  two words  "));
    QCOMPARE(s, std::string("  two words  "));
    QVERIFY(coil::stringTo(s, ""));
    QCOMPARE(s, std::string());
    QVERIFY(!coil::stringTo(s, nullptr));
}

void TestSdkCoil::stringToDurations()
{
    std::chrono::milliseconds ms(0);
    QVERIFY(coil::stringTo(ms, "1.5"));
    QCOMPARE(ms.count(), 1500LL);
    std::chrono::duration<double> seconds(0.0);
    QVERIFY(coil::stringTo(seconds, "0.25"));
    QCOMPARE(seconds.count(), 0.25);
    std::chrono::seconds s(3);
    QVERIFY(!coil::stringTo(s, "soon"));
    QCOMPARE(s.count(), 3LL);
}

void TestSdkCoil::stringToVectorViaNamespaceStdOperator()
{
    std::vector<double> gains {9.0};
    QVERIFY(coil::stringTo(gains, "1.0,2.5,-3"));
    QCOMPARE(gains, (std::vector<double> {1.0, 2.5, -3.0}));

    std::vector<int> ids;
    QVERIFY(coil::stringTo(ids, "4,5"));
    QCOMPARE(ids, (std::vector<int> {4, 5}));

    std::vector<std::string> names;
    QVERIFY(coil::stringTo(names, "a,b"));
    QCOMPARE(names, (std::vector<std::string> {"a", "b"}));
}

void TestSdkCoil::stringToContainerViaGlobalOperator()
{
    std::deque<double> values;
    QVERIFY(coil::stringTo(values, "1.5, 2.5"));
    QCOMPARE(values, (std::deque<double> {1.5, 2.5}));

    QVERIFY(!coil::stringTo(values, "1.5, x"));
    QCOMPARE(values, (std::deque<double> {1.5, 2.5})); // unchanged on failure
}

void TestSdkCoil::otosAndSprintf()
{
    QCOMPARE(coil::otos(42), std::string("42"));
    QCOMPARE(coil::otos(1.5), std::string("1.5"));
    QCOMPARE(coil::otos("text"), std::string("text"));
    QCOMPARE(coil::sprintf("%s=%d (%.2f)", "rate", 1000, 0.5), std::string("rate=1000 (0.50)"));
    QCOMPARE(coil::sprintf("%s", ""), std::string());
    const std::string longText(5000, 'x');
    QCOMPARE(coil::sprintf("[%s]", longText.c_str()), "[" + longText + "]");

    int value = 0;
    const std::string hex = coil::ptrToHex(&value);
    int *back = nullptr;
    QVERIFY(coil::hexToPtr(back, hex));
    QCOMPARE(back, &value);
    QVERIFY(!coil::hexToPtr(back, "zz"));
}

void TestSdkCoil::addressChecks()
{
    QVERIFY(coil::isIPv4("192.168.0.1"));
    QVERIFY(coil::isIPv4("0.0.0.0"));
    QVERIFY(!coil::isIPv4("256.1.1.1"));
    QVERIFY(!coil::isIPv4("1.2.3"));
    QVERIFY(!coil::isIPv4("01.2.3.4"));
    QVERIFY(coil::isIPv6("fe80:0:0:0:0:0:0:1"));
    QVERIFY(!coil::isIPv6("fe80::1"));
    QVERIFY(coil::isIPPort("2809"));
    QVERIFY(coil::isIPPort("65535"));
    QVERIFY(!coil::isIPPort("65536"));
    QVERIFY(!coil::isIPPort("port"));
    QVERIFY(coil::isURL("http://localhost"));
    QVERIFY(!coil::isURL("localhost:2809"));
    QVERIFY(coil::isAbsolutePath("/usr/lib"));
    QVERIFY(coil::isAbsolutePath("C:\\rtm"));
    QVERIFY(coil::isAbsolutePath("\\\\server\\share"));
    QVERIFY(!coil::isAbsolutePath("lib/x.so"));
    QVERIFY(!coil::isAbsolutePath(""));

    const coil::mapstring params
        = coil::urlparam2map("corbaloc::h:2809/x?interface_type=corba&id=");
    QCOMPARE(params.size(), size_t(2));
    QCOMPARE(params.at("interface_type"), std::string("corba"));
    QCOMPARE(params.at("id"), std::string());
}

void TestSdkCoil::listHelpers()
{
    QVERIFY(coil::includes(coil::vstring {"Periodic", "Event"}, "periodic"));
    QVERIFY(!coil::includes(coil::vstring {"Periodic"}, "periodic", false));
    QVERIFY(coil::includes("a, b ,c", "B"));
    QVERIFY(!coil::includes("a,b", "d"));
    QCOMPARE(coil::unique_sv({"b", "a", "b", "c", "a"}), (coil::vstring {"b", "a", "c"}));
    QCOMPARE(coil::flatten({"a", "b", "c"}), std::string("a, b, c"));
    QCOMPARE(coil::flatten({"a", "b"}, ","), std::string("a,b"));
    QCOMPARE(coil::flatten({}), std::string());

    ::setenv("TST_SDKCOIL_VAR", "value", 1);
    QCOMPARE(coil::replaceEnv("x${TST_SDKCOIL_VAR}y${TST_SDKCOIL_UNSET}z"),
             std::string("xvalueyz"));
}

void TestSdkCoil::argvHelpers()
{
    const coil::vstring args = coil::parseArgs("rtcd -o \"a b\" 'c d' e\\ f");
    QCOMPARE(args, (coil::vstring {"rtcd", "-o", "a b", "c d", "e f"}));

    coil::Argv argv(args);
    QCOMPARE(argv.size(), size_t(5));
    QCOMPARE(std::string(argv.get()[2]), std::string("a b"));
    QVERIFY(argv.get()[5] == nullptr);
    QVERIFY(coil::Argv().get() == nullptr);

    char **raw = coil::toArgv({"x", "yz"});
    QCOMPARE(std::string(raw[1]), std::string("yz"));
    QVERIFY(raw[2] == nullptr);
    for (char **p = raw; *p; ++p)
        delete[] * p;
    delete[] raw;
}

void TestSdkCoil::getlinePortableLineEnds()
{
    std::istringstream in("one\r\ntwo\rthree\nfour");
    QCOMPARE(coil::getlinePortable(in), std::string("one"));
    QCOMPARE(coil::getlinePortable(in), std::string("two"));
    std::string line;
    QCOMPARE(coil::getlinePortable(in, line), 5);
    QCOMPARE(line, std::string("three"));
    QCOMPARE(coil::getlinePortable(in), std::string("four"));
    QCOMPARE(coil::getlinePortable(in), std::string());
}

// ---------------------------------------------------------------- time, threads, OS

void TestSdkCoil::timeValueNormalises_data()
{
    QTest::addColumn<long>("sec");
    QTest::addColumn<long>("usec");
    QTest::addColumn<long>("expectedSec");
    QTest::addColumn<long>("expectedUsec");

    QTest::newRow("in range") << 1L << 500000L << 1L << 500000L;
    QTest::newRow("usec overflow") << 1L << 2500000L << 3L << 500000L;
    QTest::newRow("negative usec borrows") << 2L << -250000L << 1L << 750000L;
    QTest::newRow("negative total") << 0L << -1500000L << -1L << -500000L;
    QTest::newRow("negative seconds") << -2L << 500000L << -1L << -500000L;
    QTest::newRow("zero") << 0L << 0L << 0L << 0L;
}

void TestSdkCoil::timeValueNormalises()
{
    QFETCH(long, sec);
    QFETCH(long, usec);
    QFETCH(long, expectedSec);
    QFETCH(long, expectedUsec);
    const coil::TimeValue tv(sec, usec);
    QCOMPARE(tv.sec(), expectedSec);
    QCOMPARE(tv.usec(), expectedUsec);
}

void TestSdkCoil::timeValueFromDouble_data()
{
    QTest::addColumn<double>("seconds");
    QTest::addColumn<long>("expectedSec");
    QTest::addColumn<long>("expectedUsec");

    QTest::newRow("1.5") << 1.5 << 1L << 500000L;
    QTest::newRow("-1.5") << -1.5 << -1L << -500000L;
    QTest::newRow("rounds to usec") << 0.0000014 << 0L << 1L;
    QTest::newRow("rounds up into a second") << 0.9999999 << 1L << 0L;
    QTest::newRow("nan") << qQNaN() << 0L << 0L;
}

void TestSdkCoil::timeValueFromDouble()
{
    QFETCH(double, seconds);
    QFETCH(long, expectedSec);
    QFETCH(long, expectedUsec);
    const coil::TimeValue tv(seconds);
    QCOMPARE(tv.sec(), expectedSec);
    QCOMPARE(tv.usec(), expectedUsec);
    coil::TimeValue assigned;
    assigned = seconds;
    QCOMPARE(assigned.sec(), expectedSec);
    QCOMPARE(assigned.usec(), expectedUsec);
}

void TestSdkCoil::timeValueArithmetic()
{
    const coil::TimeValue a(1, 700000);
    const coil::TimeValue b(0, 400000);
    QCOMPARE((a + b).sec(), 2L);
    QCOMPARE((a + b).usec(), 100000L);
    QCOMPARE((a - b).usec(), 300000L);
    QCOMPARE((b - a).sec(), -1L);
    QCOMPARE((b - a).usec(), -300000L);
    QCOMPARE((b - a).sign(), -1);
    QCOMPARE(coil::TimeValue().sign(), 0);
    QCOMPARE(static_cast<double>(a), 1.7);

    coil::TimeValue c = a;
    c += b;
    QVERIFY(c == coil::TimeValue(2, 100000));
    c -= coil::TimeValue(3.0);
    QVERIFY(c == coil::TimeValue(0, -900000));
    QVERIFY(c != a);
    QVERIFY(b < a);
    QVERIFY(a > b);
    QVERIFY(a <= a);
    QVERIFY(a >= b);

    // Mixed with numbers a TimeValue reads as seconds, as in OpenRTM-aist 1.x.
    QCOMPARE(a + 0.3, 2.0);
    QVERIFY(a > 1.0);
    c = 5;
    QCOMPARE(c.sec(), 5L);
}

void TestSdkCoil::timeFunctions()
{
    const coil::TimeValue first = coil::gettimeofday();
    QVERIFY(first.sec() > 1500000000L); // after 2017: a real wall clock
    QCOMPARE(coil::usleep(1000), 0);
    QCOMPARE(coil::sleep(coil::TimeValue(0, 1000)), 0);
    QCOMPARE(coil::sleep(coil::TimeValue(-1.0)), -1);
    coil::TimeValue second;
    QCOMPARE(coil::gettimeofday(second), 0);
    const double elapsed = second - first;
    QVERIFY2(elapsed >= 0.0015 && elapsed < 60.0, qPrintable(QString::number(elapsed)));
    timeval tv;
    QCOMPARE(coil::gettimeofday(&tv, nullptr), 0);
}

void TestSdkCoil::mutexAndGuard()
{
    coil::Mutex mutex("named");
    bool otherGotIt = true;
    {
        coil::Guard<coil::Mutex> guard(mutex);
        std::thread other([&] {
            otherGotIt = !mutex.trylock(); // trylock() answers "failed?"
            if (otherGotIt)
                mutex.unlock();
        });
        other.join();
    }
    QVERIFY(!otherGotIt);
    QVERIFY(!mutex.trylock());
    mutex.unlock();

    int counter = 0;
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] {
            for (int i = 0; i < 10000; ++i) {
                coil::Guard<coil::Mutex> guard(mutex);
                ++counter;
            }
        });
    for (std::thread &t : threads)
        t.join();
    QCOMPARE(counter, 40000);
}

void TestSdkCoil::conditionTimesOut()
{
    coil::Mutex mutex;
    coil::Condition<coil::Mutex> condition(mutex);
    coil::Guard<coil::Mutex> guard(mutex);
    QVERIFY(!condition.wait(0, 1000000)); // nobody signals: times out after 1 ms
}

void TestSdkCoil::singletonCreatesOnce()
{
    std::vector<std::thread> threads;
    std::vector<Counter *> seen(8, nullptr);
    for (size_t t = 0; t < seen.size(); ++t)
        threads.emplace_back([&seen, t] { seen[t] = &Counter::instance(); });
    for (std::thread &t : threads)
        t.join();
    for (Counter *c : seen)
        QCOMPARE(c, &Counter::instance());
    QCOMPARE(Counter::constructed.load(), 1);
}

void TestSdkCoil::taskRunsSvcInThread()
{
    RecordingTask task;
    QCOMPARE(task.wait(), 0); // nothing to join yet
    QCOMPARE(task.open(), 0);
    task.activate();
    QCOMPARE(task.wait(), 0);
    QCOMPARE(task.runs.load(), 1);
    QCOMPARE(task.finalized.load(), 1);
    QVERIFY(task.svcThread != std::this_thread::get_id());

    // finalize() reset the task, so it can run again.
    task.activate();
    task.wait();
    QCOMPARE(task.runs.load(), 2);
    QCOMPARE(task.close(), 0);
}

void TestSdkCoil::timeMeasure()
{
    coil::TimeMeasure measure(3);
    QCOMPARE(measure.count(), 0UL);
    double maxI = -1, minI = -1, meanI = -1, dev = -1;
    QVERIFY(!measure.getStatistics(maxI, minI, meanI, dev));
    measure.tack(); // without tick: ignored
    QCOMPARE(measure.count(), 0UL);
    for (int i = 0; i < 5; ++i) {
        measure.tick();
        measure.tack();
    }
    QCOMPARE(measure.count(), 3UL);
    QVERIFY(measure.interval().count() >= 0);
    const coil::TimeMeasure::Statistics stats = measure.getStatistics();
    QVERIFY(stats.min_interval >= 0.0);
    QVERIFY(stats.min_interval <= stats.mean_interval);
    QVERIFY(stats.mean_interval <= stats.max_interval);
    QVERIFY(stats.std_deviation >= 0.0);
    measure.reset();
    QCOMPARE(measure.count(), 0UL);
}

void TestSdkCoil::osWrappers()
{
    ::setenv("TST_SDKCOIL_ENV", "here", 1);
    std::string value;
    QVERIFY(coil::getenv("TST_SDKCOIL_ENV", value));
    QCOMPARE(value, std::string("here"));
    QVERIFY(!coil::getenv("TST_SDKCOIL_NOT_SET_ANYWHERE", value));
    QCOMPARE(std::string(coil::getenv("TST_SDKCOIL_ENV")), std::string("here"));
    QVERIFY(coil::getenv("TST_SDKCOIL_NOT_SET_ANYWHERE") == nullptr);
    QCOMPARE(coil::getpid(), ::getpid());
    coil::utsname name;
    QCOMPARE(coil::uname(&name), 0);
}

void TestSdkCoil::getOpt()
{
    char arg0[] = "comp", arg1[] = "-f", arg2[] = "rtc.conf", arg3[] = "-d", arg4[] = "rest";
    char *argv[] = {arg0, arg1, arg2, arg3, arg4, nullptr};
    coil::GetOpt get(5, argv, "f:d", 0);
    QCOMPARE(get(), int('f'));
    QCOMPARE(std::string(get.optarg), std::string("rtc.conf"));
    QCOMPARE(get(), int('d'));
    QCOMPARE(get(), -1);
    QCOMPARE(std::string(argv[get.optind]), std::string("rest"));
}

void TestSdkCoil::uuid()
{
    coil::UUID *a = coil::UUID_Generator::generateUUID(0, 0);
    coil::UUID b;
    const std::string textA = a->to_string();
    const QRegularExpression format(
        QStringLiteral("^[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}$"));
    QVERIFY2(format.match(QString::fromStdString(textA)).hasMatch(), textA.c_str());
    QVERIFY(textA != std::string(b.to_string()));
    delete a;

    coil::UUID_Generator generator; // the 1.x way
    generator.init();
    coil::UUID *c = generator.generateUUID(2, 0x01);
    QVERIFY(format.match(QString::fromLatin1(c->to_string())).hasMatch());
    delete c;
}

void TestSdkCoil::clocks()
{
    coil::ClockManager &clocks = coil::ClockManager::instance();
    QCOMPARE(&clocks, &coil::ClockManager::instance());

    coil::IClock &logical = clocks.getClock("logical");
    QVERIFY(logical.settime(std::chrono::seconds(42)));
    QCOMPARE(logical.gettime(), std::chrono::nanoseconds(std::chrono::seconds(42)));

    coil::IClock &system = clocks.getClock("system");
    QCOMPARE(&clocks.getClock("anything else"), &system);
    QVERIFY(!system.settime(std::chrono::seconds(0)));
    const auto now = std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::system_clock::now().time_since_epoch());
    QVERIFY(std::chrono::abs(system.gettime() - now) < std::chrono::seconds(5));

    coil::IClock &adjusted = clocks.getClock("adjusted");
    QVERIFY(adjusted.settime(std::chrono::hours(1)));
    const auto adjustedNow = adjusted.gettime();
    QVERIFY(adjustedNow >= std::chrono::hours(1));
    QVERIFY(adjustedNow < std::chrono::hours(1) + std::chrono::seconds(5));
}

void TestSdkCoil::files()
{
    QCOMPARE(coil::dirname("/usr/lib/x.so"), std::string("/usr/lib"));
    QCOMPARE(coil::dirname("x.so"), std::string("."));
    QCOMPARE(coil::basename("/usr/lib/x.so"), std::string("x.so"));
    QCOMPARE(coil::dirname("/usr/lib/"), std::string("/usr"));
    QCOMPARE(coil::basename("/usr/lib/"), std::string("lib"));
    QCOMPARE(coil::dirname("/x"), std::string("/"));
    QCOMPARE(coil::dirname("//"), std::string("/"));
    QCOMPARE(coil::basename("//"), std::string("/"));
    QCOMPARE(coil::dirname(""), std::string("."));
    QCOMPARE(coil::basename(""), std::string("."));
    QCOMPARE(coil::basename("x"), std::string("x"));
    QCOMPARE(coil::dirname("a//b"), std::string("a"));

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("sub/deeper")));
    for (const char *name : {"A.so", "B.so", "notes.txt", "sub/C.so", "sub/deeper/A.so"}) {
        QFile file(dir.filePath(QString::fromLatin1(name)));
        QVERIFY(file.open(QIODevice::WriteOnly));
    }
    const std::string root = dir.path().toStdString();

    coil::vstring names = coil::filelist(root.c_str(), "*.so");
    std::sort(names.begin(), names.end());
    QCOMPARE(names, (coil::vstring {"A.so", "B.so"}));
    names = coil::filelist(root.c_str(), "+.txt");
    QCOMPARE(names, (coil::vstring {"notes.txt"}));
    QCOMPARE(coil::filelist(root.c_str()).size(), size_t(6)); // with ".", ".." and "sub"
    QVERIFY(coil::filelist("/no/such/dir").empty());

    coil::vstring found;
    coil::findFile(root, "A.so", found);
    std::sort(found.begin(), found.end());
    QCOMPARE(found, (coil::vstring {root + "/A.so", root + "/sub/deeper/A.so"}));

    coil::vstring libraries;
    coil::getFileList(root, "so", libraries);
    QCOMPARE(libraries.size(), size_t(4));
}

void TestSdkCoil::dynamicLib()
{
    coil::DynamicLib lib;
    QCOMPARE(lib.open("libm.so.6"), 0);
    using Cosine = double (*)(double);
    Cosine cosine = reinterpret_cast<Cosine>(lib.symbol("cos"));
    QVERIFY(cosine);
    QCOMPARE(cosine(0.0), 1.0);
    QVERIFY(!lib.symbol("no_such_symbol_in_libm"));

    coil::DynamicLib copy(lib);
    QVERIFY(copy.symbol("cos"));
    QCOMPARE(lib.close(), 0);
    QCOMPARE(lib.close(), -1);
    QVERIFY(!lib.symbol("cos"));

    coil::DynamicLib missing;
    QCOMPARE(missing.open("/no/such/library.so"), -1);
    QVERIFY(coil::DynamicLib::error() != nullptr);
    QVERIFY(!missing.symbol("cos"));
}

void TestSdkCoil::nonCopyable()
{
    class Resource : private coil::NonCopyable
    {
    };
    static_assert(!std::is_copy_constructible<Resource>::value, "NonCopyable forbids copies");
    static_assert(!std::is_copy_assignable<Resource>::value, "NonCopyable forbids assignment");
    static_assert(std::is_default_constructible<Resource>::value, "still constructible");
}

void TestSdkCoil::asyncInvoker()
{
    struct Robot
    {
        std::atomic<int> homed {0};
        void home() { ++homed; }
    } robot;

    coil::Async *call = coil::AsyncInvoker(&robot, [](Robot *r) { r->home(); });
    call->invoke();
    QTRY_VERIFY(call->finished());
    QCOMPARE(robot.homed.load(), 1);
    call->exit();

    // A function object the caller keeps, called through a reference.
    struct Homing
    {
        int calls = 0;
        void operator()(Robot *r)
        {
            ++calls;
            r->home();
        }
    } homing;
    coil::Async *byRef = coil::AsyncInvoker(&robot, &homing);
    byRef->invoke();
    byRef->exit();
    QCOMPARE(homing.calls, 1);
    QCOMPARE(robot.homed.load(), 2);

    // Calls that delete themselves when done.
    for (int i = 0; i < 20; ++i)
        coil::AsyncInvoker(
            &robot, [](Robot *r) { r->home(); }, true)
            ->invoke();
    QTRY_COMPARE(robot.homed.load(), 22);
}

void TestSdkCoil::periodicTask()
{
    std::atomic<int> calls {0};
    coil::PeriodicTask task;
    task.activate(); // no function yet: nothing starts
    task.setTask([&calls] { ++calls; });
    task.setPeriod(std::chrono::milliseconds(1));
    task.executionMeasure(true);
    task.executionMeasureCount(2);
    task.periodicMeasure(true);
    task.periodicMeasureCount(2);
    task.activate();
    task.activate(); // already running: no second thread
    QTRY_VERIFY(calls.load() >= 5);
    QTRY_VERIFY(task.getPeriodStat().max_interval > 0.0);
    const coil::TimeMeasure::Statistics exec = task.getExecStat();
    QVERIFY(exec.min_interval >= 0.0 && exec.min_interval <= exec.max_interval);

    task.suspend();
    const int beforeSignal = calls.load();
    task.signal(); // one more call although suspended
    QTRY_VERIFY(calls.load() > beforeSignal);
    task.resume();
    const int resumedFrom = calls.load();
    QTRY_VERIFY(calls.load() > resumedFrom + 2);

    task.finalize();
    task.wait();
    const int stoppedAt = calls.load();
    task.activate(); // runs again after a stop
    QTRY_VERIFY(calls.load() > stoppedAt);
}

void TestSdkCoil::periodicTaskStopsWithoutWaitingForThePeriod()
{
    std::atomic<int> calls {0};
    QElapsedTimer timer;
    timer.start();
    {
        coil::PeriodicTask task;
        task.setTask([&calls] { ++calls; });
        task.setPeriod(std::chrono::seconds(30));
        task.activate();
        QTRY_COMPARE(calls.load(), 1);
    } // the destructor stops and joins the thread
    QVERIFY2(timer.elapsed() < 10000, qPrintable(QString::number(timer.elapsed())));
    QCOMPARE(calls.load(), 1);
}

void TestSdkCoil::checksums_data()
{
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<uint>("crc16");
    QTest::addColumn<qulonglong>("crc32");

    // The standard check values of CRC-16/CCITT-FALSE and CRC-32.
    QTest::newRow("check string") << QByteArray("123456789") << 0x29B1u << 0xCBF43926ull;
    QTest::newRow("empty") << QByteArray() << 0xFFFFu << 0x0ull;
    QTest::newRow("high bytes") << QByteArray("\xff\x80") << 0x8F78u << 0x3F456CADull;
}

void TestSdkCoil::checksums()
{
    QFETCH(QByteArray, data);
    QFETCH(uint, crc16);
    QFETCH(qulonglong, crc32);
    QCOMPARE(uint(coil::crc16(data.constData(), size_t(data.size()))), crc16);
    QCOMPARE(qulonglong(coil::crc32(data.constData(), size_t(data.size()))), crc32);
}

void TestSdkCoil::processes()
{
    coil::vstring out {"stale"};
    QCOMPARE(coil::create_process("printf 'one\\ntwo words\\nlast'", out), 0);
    QCOMPARE(out, (coil::vstring {"one", "two words", "last"}));

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString marker = dir.filePath(QStringLiteral("started by launch_shell"));
    QCOMPARE(coil::launch_shell("touch \"" + marker.toStdString() + "\""), 0);
    QTRY_VERIFY(QFileInfo::exists(marker));
    QCOMPARE(coil::launch_shell(""), -1);
}

namespace {
volatile sig_atomic_t g_signalSeen = 0;
extern "C" void recordSignal(int signum)
{
    g_signalSeen = signum;
}
} // namespace

void TestSdkCoil::signalAction()
{
    {
        coil::SignalAction action(recordSignal, SIGUSR2);
        QCOMPARE(::raise(SIGUSR2), 0);
        QCOMPARE(int(g_signalSeen), SIGUSR2);
        struct sigaction current;
        QCOMPARE(::sigaction(SIGUSR2, nullptr, &current), 0);
        QVERIFY(current.sa_handler == recordSignal);
    }
    struct sigaction restored;
    QCOMPARE(::sigaction(SIGUSR2, nullptr, &restored), 0);
    QVERIFY(restored.sa_handler == SIG_DFL);
}

// ---------------------------------------------------------------- Timer

void TestSdkCoil::timerCallsAtTheirInterval()
{
    using std::chrono::milliseconds;
    coil::Timer<coil::PeriodicFunction> periodic;
    int fast = 0;
    int slow = 0;
    coil::Timer<coil::PeriodicFunction>::TaskId fastId = periodic.emplace([&fast] { ++fast; },
                                                                         milliseconds(20));
    periodic.emplace([&slow] { ++slow; }, milliseconds(50));
    for (int i = 0; i < 10; ++i)
        periodic.tick(milliseconds(10));
    QCOMPARE(fast, 5);
    QCOMPARE(slow, 2);
    fastId->stop();
    for (int i = 0; i < 10; ++i)
        periodic.tick(milliseconds(10));
    QCOMPARE(fast, 5);
    QCOMPARE(slow, 4);

    coil::Timer<coil::DelayedFunction> delayed;
    int once = 0;
    delayed.emplace([&once] { ++once; }, milliseconds(25));
    delayed.tick(milliseconds(10));
    delayed.tick(milliseconds(10));
    QCOMPARE(once, 0);
    delayed.tick(milliseconds(10));
    QCOMPARE(once, 1);
    for (int i = 0; i < 5; ++i)
        delayed.tick(milliseconds(10));
    QCOMPARE(once, 1);

    // Driven by a thread as the manager drives its timers: a stopped task stays silent while
    // the others go on.
    coil::Timer<coil::PeriodicFunction> clocked;
    std::atomic<int> stopped {0};
    std::atomic<int> running {0};
    coil::Timer<coil::PeriodicFunction>::TaskId stoppedId = clocked.emplace([&stopped] { ++stopped; },
                                                                            milliseconds(2));
    clocked.emplace([&running] { ++running; }, milliseconds(2));
    coil::PeriodicTask driver;
    driver.setTask([&clocked] { clocked.tick(std::chrono::milliseconds(1)); });
    driver.setPeriod(milliseconds(1));
    driver.activate();
    QTRY_VERIFY(stopped.load() >= 3);
    stoppedId->stop();
    const int runningAtStop = running.load();
    QTRY_VERIFY(running.load() >= runningAtStop + 2); // at least one full tick after stop()
    const int stoppedAt = stopped.load();
    QTRY_VERIFY(running.load() >= runningAtStop + 6);
    QCOMPARE(stopped.load(), stoppedAt);
    driver.finalize();
    driver.wait();
}

void TestSdkCoil::timerTasksMayAddTasks()
{
    using std::chrono::milliseconds;
    coil::Timer<coil::DelayedFunction> timer;
    int second = 0;
    timer.emplace([&timer, &second] { timer.emplace([&second] { ++second; }, milliseconds(10)); },
                  milliseconds(10));
    timer.tick(milliseconds(10)); // runs the first, which adds the second
    QCOMPARE(second, 0);
    timer.tick(milliseconds(10));
    QCOMPARE(second, 1);

    // Tasks held by pointer, as the manager keeps them.
    coil::Timer<std::unique_ptr<coil::PeriodicFunction>> owned;
    int calls = 0;
    owned.emplace(new coil::PeriodicFunction([&calls] { ++calls; }, milliseconds(5)));
    owned.tick(milliseconds(5));
    owned.tick(milliseconds(5));
    QCOMPARE(calls, 2);
}

// ---------------------------------------------------------------- Factory

void TestSdkCoil::factory()
{
    coil::Factory<Shape> factory;
    QVERIFY(factory.addFactory("triangle", coil::Creator<Shape, Triangle>, coil::Destructor<Shape, Triangle>)
            == coil::FactoryReturn::OK);
    coil::Properties squareInfo;
    squareInfo.setProperty("corners", "4");
    QVERIFY(factory.addFactory("square", coil::Creator<Shape, Square>, coil::Destructor<Shape, Square>,
                               squareInfo)
            == coil::FactoryReturn::OK);
    QVERIFY(factory.addFactory("square", coil::Creator<Shape, Square>, coil::Destructor<Shape, Square>)
            == coil::FactoryReturn::ALREADY_EXISTS);
    QVERIFY(factory.addFactory("circle", nullptr, coil::Destructor<Shape, Square>)
            == coil::FactoryReturn::INVALID_ARG);
    QCOMPARE(factory.getIdentifiers(), (std::vector<std::string> {"square", "triangle"}));
    QVERIFY(factory.hasFactory("square"));
    QVERIFY(!factory.hasFactory("circle"));
    QCOMPARE(factory.getProperties("square").getProperty("corners"), std::string("4"));

    Shape *triangle = factory.createObject("triangle");
    QVERIFY(triangle != nullptr);
    QCOMPARE(triangle->corners(), 3);
    QVERIFY(factory.createObject("circle") == nullptr); // unknown identifier
    Shape *square = factory.createObject("square");
    QCOMPARE(square->corners(), 4);
    QCOMPARE(factory.createdObjects().size(), size_t(2));
    QVERIFY(factory.isProducerOf(triangle));
    std::string id;
    QVERIFY(factory.objectToIdentifier(square, id) == coil::FactoryReturn::OK);
    QCOMPARE(id, std::string("square"));
    QVERIFY((factory.objectToCreator(square) == &coil::Creator<Shape, Square>));
    QVERIFY((factory.objectToDestructor(square) == &coil::Destructor<Shape, Square>));

    Shape *foreign = new Square();
    QVERIFY(!factory.isProducerOf(foreign));
    QVERIFY(factory.objectToIdentifier(foreign, id) == coil::FactoryReturn::NOT_FOUND);
    QVERIFY(factory.deleteObject(foreign) == coil::FactoryReturn::NOT_FOUND);
    QVERIFY(foreign != nullptr);
    delete foreign;

    QVERIFY(factory.deleteObject(triangle) == coil::FactoryReturn::OK);
    QVERIFY(triangle == nullptr);
    QVERIFY(factory.deleteObject("square", square) == coil::FactoryReturn::OK);
    QVERIFY(square == nullptr);
    QVERIFY(factory.createdObjects().empty());

    QVERIFY(factory.removeFactory("triangle") == coil::FactoryReturn::OK);
    QVERIFY(factory.removeFactory("triangle") == coil::FactoryReturn::NOT_FOUND);
    QVERIFY(factory.createObject("triangle") == nullptr);
    QCOMPARE(factory.getIdentifiers(), std::vector<std::string> {"square"});
}

void TestSdkCoil::globalFactoryIsShared()
{
    typedef coil::GlobalFactory<Shape> ShapeFactory;
    QCOMPARE(&ShapeFactory::instance(), &ShapeFactory::instance());
    QVERIFY(ShapeFactory::instance().addFactory("triangle", coil::Creator<Shape, Triangle>,
                                                coil::Destructor<Shape, Triangle>)
            == coil::FactoryReturn::OK);
    Shape *shape = ShapeFactory::instance().createObject("triangle");
    QVERIFY(shape != nullptr);
    QVERIFY(ShapeFactory::instance().deleteObject(shape) == coil::FactoryReturn::OK);
    QVERIFY(ShapeFactory::instance().removeFactory("triangle") == coil::FactoryReturn::OK);
}

// ---------------------------------------------------------------- Logger

void TestSdkCoil::logStreamLevels()
{
    MemoryLogBuffer buffer;
    NamedLogStream log(&buffer, 4); // INFO in OpenRTM's numbering
    QCOMPARE(log.getLevel(), 4);
    QVERIFY(log.isValid(1));
    QVERIFY(log.isValid(4));
    QVERIFY(!log.isValid(5));
    log.write(3, "warning");
    log.write(5, "debug");
    QCOMPARE(buffer.lines, std::vector<std::string> {"3 test: warning"});

    QVERIFY(!log.setLevel(9)); // above the maximum: refused
    QCOMPARE(log.getLevel(), 4);
    QVERIFY(!log.setLevel(-1));
    QVERIFY(log.setLevel(6));
    QVERIFY(log.isValid(5));
    QVERIFY(!log.isValid(7));
    log.write(5, "debug");
    QCOMPARE(buffer.lines.size(), size_t(2));
    QVERIFY(log.setLevel(0));
    QVERIFY(!log.isValid(1));

    log.flush();
    QCOMPARE(buffer.flushes, 1);

    coil::LogStream::disableLock();
    QVERIFY(!coil::LogStream::m_lockEnable);
    coil::LogStream::enableLock();
    coil::LogStream::lock();
    QVERIFY(!coil::LogStream::m_mutex.try_lock()); // held by lock()
    coil::LogStream::unlock();
    QVERIFY(coil::LogStream::m_mutex.try_lock());
    coil::LogStream::m_mutex.unlock();
}

void TestSdkCoil::logStreamBufferFansOut()
{
    int destroyed = 0;
    MemoryLogBuffer kept;
    MemoryLogBuffer *owned = new MemoryLogBuffer(&destroyed);
    {
        coil::LogStreamBuffer root;
        root.addStream(owned, true);
        root.addStream(&kept);
        // Enough entries that the list grows several times: ownership must survive that.
        std::vector<MemoryLogBuffer *> more;
        for (int i = 0; i < 5; ++i) {
            more.push_back(new MemoryLogBuffer(&destroyed));
            root.addStream(more.back(), true);
        }
        QCOMPARE(root.getBuffers().size(), size_t(7));
        QVERIFY(root.getBuffers()[1] == &kept);
        root.write(2, "comp", "date", "hello");
        QCOMPARE(owned->lines, std::vector<std::string> {"2 comp: hello"});
        QCOMPARE(kept.lines, std::vector<std::string> {"2 comp: hello"});
        QCOMPARE(more.back()->lines.size(), size_t(1));
        root.flush();
        QCOMPARE(kept.flushes, 1);

        QVERIFY(root.removeStream(&kept));
        QVERIFY(!root.removeStream(&kept));
        root.write(2, "comp", "date", "again");
        QCOMPARE(kept.lines.size(), size_t(1));
        QCOMPARE(owned->lines.size(), size_t(2));
    }
    QCOMPARE(destroyed, 6); // the owned ones, not the one it was only lent
}

// ---------------------------------------------------------------- Affinity

void TestSdkCoil::threadAffinity()
{
    coil::CpuMask process;
    QVERIFY(coil::getProcCpuAffinity(process));
    QVERIFY(!process.empty());

    // In a thread of its own, so that the test's thread keeps all its CPUs.
    coil::CpuMask before, pinned, fromText, restored;
    bool setOk = false, textOk = false, badText = true, empty = true, restoreOk = false;
    std::thread worker([&] {
        coil::getThreadCpuAffinity(before);
        if (before.empty())
            return;
        setOk = coil::setThreadCpuAffinity(coil::CpuMask {before.back()});
        coil::getThreadCpuAffinity(pinned);
        textOk = coil::setThreadCpuAffinity(std::to_string(before.front()));
        coil::getThreadCpuAffinity(fromText);
        badText = coil::setThreadCpuAffinity(std::string("one,two"));
        empty = coil::setThreadCpuAffinity(coil::CpuMask());
        restoreOk = coil::setThreadCpuAffinity(before);
        coil::getThreadCpuAffinity(restored);
    });
    worker.join();
    QCOMPARE(before, process);
    QVERIFY(setOk);
    QCOMPARE(pinned, coil::CpuMask {before.back()});
    QVERIFY(textOk);
    QCOMPARE(fromText, coil::CpuMask {before.front()});
    QVERIFY(!badText);
    QVERIFY(!empty);
    QVERIFY(restoreOk);
    QCOMPARE(restored, before);
}

// ---------------------------------------------------------------- SharedMemory

void TestSdkCoil::sharedMemory()
{
    const std::string name = "rtstudio_tst_sdkcoil_" + std::to_string(QCoreApplication::applicationPid());
    coil::SharedMemory writer;
    QCOMPARE(writer.create(name, 4096), 0);
    QVERIFY(writer.created());
    QCOMPARE(writer.get_size(), 4096ULL);
    QCOMPARE(writer.get_addresss(), name);
    QVERIFY(writer.get_data() != nullptr);
    const char text[] = "hello over shared memory";
    QCOMPARE(writer.write(text, 100, sizeof(text)), 0);
    QCOMPARE(writer.write(text, 4090, sizeof(text)), -1); // past the end

    coil::SharedMemory reader;
    QCOMPARE(reader.open("/" + name, 4096), 0); // the same segment, with or without the slash
    QVERIFY(!reader.created());
    char back[sizeof(text)] = {0};
    QCOMPARE(reader.read(back, 100, sizeof(back)), 0);
    QCOMPARE(QByteArray(back), QByteArray(text));
    QCOMPARE(reader.write("HELLO", 100, 5), 0);
    QCOMPARE(writer.read(back, 100, sizeof(back)), 0);
    QCOMPARE(QByteArray(back), QByteArray("HELLO over shared memory"));
    QCOMPARE(reader.read(back, 5000, 1), -1);

    coil::SharedMemory copy(reader); // a mapping of its own
    QCOMPARE(reader.close(), 0);
    QCOMPARE(reader.close(), -1);
    QCOMPARE(copy.read(back, 100, 5), 0);
    QCOMPARE(QByteArray(back, 5), QByteArray("HELLO"));

    QCOMPARE(writer.unlink(), 0);
    coil::SharedMemory late;
    QCOMPARE(late.open(name, 4096), -1); // the name is gone
    QCOMPARE(writer.read(back, 100, 5), 0); // the mapping itself stays valid
    QCOMPARE(writer.close(), 0);
}

void TestSdkCoil::sharedMemoryMissingName()
{
    coil::SharedMemory memory;
    QCOMPARE(memory.open("rtstudio_tst_sdkcoil_no_such_segment", 4096), -1);
    QVERIFY(memory.get_data() == nullptr);
    char byte = 0;
    QCOMPARE(memory.read(&byte, 0, 1), -1);
    QCOMPARE(memory.write(&byte, 0, 1), -1);
    QCOMPARE(memory.unlink(), -1);
    QCOMPARE(memory.create("", 4096), -1);

    const std::string name = "rtstudio_tst_sdkcoil_small_" + std::to_string(QCoreApplication::applicationPid());
    coil::SharedMemory small;
    QCOMPARE(small.create(name, 16), 0);
    coil::SharedMemory larger;
    QCOMPARE(larger.open(name, 4096), -1); // more than the segment has
    QCOMPARE(small.unlink(), 0);
}

// ---------------------------------------------------------------- Routing

void TestSdkCoil::routingToLoopback()
{
    std::string endpoint;
    QVERIFY(coil::dest_to_endpoint("127.0.0.1", endpoint));
    QCOMPARE(endpoint, std::string("127.0.0.1"));
    std::string ifname;
    QVERIFY(coil::find_dest_ifname("127.0.0.1", ifname));
    QVERIFY(!ifname.empty());
    std::string address;
    QVERIFY(coil::ifname_to_ipaddr(ifname, address));
    QCOMPARE(address, std::string("127.0.0.1"));

    QVERIFY(!coil::dest_to_endpoint("", endpoint));
    QVERIFY(!coil::find_dest_ifname("", ifname));
    QVERIFY(!coil::ifname_to_ipaddr("rtstudio-none0", address));
}

// ---------------------------------------------------------------- Async

namespace {
struct GatedCall
{
    std::shared_ptr<int> token;
    std::atomic<bool> *gate;
    void operator()(int *) const
    {
        while (!gate->load())
            std::this_thread::yield();
    }
};
} // namespace

void TestSdkCoil::deleteAsyncThread()
{
    std::atomic<bool> gate {false};
    std::shared_ptr<int> token = std::make_shared<int>(0);
    std::weak_ptr<int> alive = token;
    int object = 0;
    coil::DeleteAsyncThread sweeper;
    coil::Async *call = coil::AsyncInvoker(&object, GatedCall {token, &gate});
    token.reset();
    sweeper.add(call);
    call->invoke();
    QVERIFY(!alive.expired()); // still running: not deleted
    gate = true;
    QTRY_VERIFY(alive.expired()); // finished, then deleted by the sweep
    QVERIFY(coil::DeleteAsyncThread::instance() == coil::DeleteAsyncThread::instance());
}

QTEST_APPLESS_MAIN(TestSdkCoil)
#include "tst_sdkcoil.moc"

// SPDX-License-Identifier: MIT
// Data port samples decoded and encoded by IDL type, checked byte for byte against what omniORB's
// own stubs marshal for the same values (the bytes every OpenRTM-aist OutPort sends).

#include "cdrcodec.h"
#include "idltypelibrary.h"

#include <BasicDataType.hh>
#include <ExtendedDataTypes.hh>
#include <InterfaceDataTypes.hh>
#include <RTC.hh>
#include <SDOPackage.hh>

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <functional>

using Codegen::CdrCodec;

namespace {

template <typename T>
QByteArray marshal(const T &value)
{
    cdrMemoryStream stream;
    value >>= stream;
    return QByteArray(static_cast<const char *>(stream.bufPtr()), int(stream.bufSize()));
}

/// omniORB leaves alignment padding as it finds it: two samples are the same when their sizes and
/// their bytes outside padding (seen through decoding) are.
bool sameSample(const CdrCodec &codec, const char *type, const QByteArray &ours, const QByteArray &theirs)
{
    QString error;
    return ours.size() == theirs.size()
        && codec.decode(type, ours, true, &error) == codec.decode(type, theirs, true, &error)
        && error.isEmpty();
}

QJsonObject json(const char *text)
{
    return QJsonDocument::fromJson(text).object();
}

} // namespace

class TestCdrCodec : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void typeNames();
    void matchesOmniOrb();
    void wideCharactersMatchOmniOrb_data();
    void wideCharactersMatchOmniOrb();
    void unionsMatchOmniOrb();
    void anysMatchOmniOrb_data();
    void anysMatchOmniOrb();
    void constructedAnysMatchOmniOrb_data();
    void constructedAnysMatchOmniOrb();
    void namedTypesRepeatedInATypeCodeAreIndirections();
    void typeCodeValuesMatchOmniOrb();
    void anyOfAnUndeclaredTypeIsRefused();
    void objectReferencesMatchOmniOrb();
    void bigEndianRoundTrip();
    void malformedSamplesAreReported_data();
    void malformedSamplesAreReported();
    void badValuesAreReported_data();
    void badValuesAreReported();
    void commandLineValues();
    void textAndJsonForms();

private:
    CORBA::ORB_var m_orb;
    Codegen::IdlTypeLibrary m_library {{RTSTUDIO_IDL_DIR}};
};

void TestCdrCodec::initTestCase()
{
    // omniORB marshals strings through the code set converters ORB_init sets up.
    int argc = 1;
    char name[] = "tst_cdrcodec";
    char *argv[] = {name, nullptr};
    m_orb = CORBA::ORB_init(argc, argv);
    // OpenRTM's data types (SDOPackage.idl's include of omniORB's orb.idl does not matter here).
    for (const char *type : {"RTC::TimedLong", "RTC::TimedPose2D", "RTC::CameraImage", "RTC::GPSData"})
        QVERIFY2(m_library.model().structs.contains(QLatin1String(type)), type);
}

void TestCdrCodec::cleanupTestCase()
{
    m_orb->destroy();
}

void TestCdrCodec::typeNames()
{
    QCOMPARE(CdrCodec::typeName("IDL:RTC/TimedLong:1.0"), QString("RTC::TimedLong"));
    QCOMPARE(CdrCodec::typeName("IDL:Sensor/Nested/Scan:2.1"), QString("Sensor::Nested::Scan"));
    QCOMPARE(CdrCodec::typeName("RTC::TimedLong"), QString("RTC::TimedLong"));
    const CdrCodec codec(m_library.model());
    QVERIFY(codec.knows("RTC::TimedDoubleSeq"));
    QVERIFY(!codec.knows("RTC::NoSuchType"));
}

void TestCdrCodec::matchesOmniOrb()
{
    const CdrCodec codec(m_library.model());
    QString error;

    RTC::TimedLong timedLong;
    timedLong.tm.sec = 1732712345;
    timedLong.tm.nsec = 123456789;
    timedLong.data = -42;
    const QJsonObject expectedLong = json(R"({"tm":{"sec":1732712345,"nsec":123456789},"data":-42})");
    QCOMPARE(codec.decode("RTC::TimedLong", marshal(timedLong), true, &error), QJsonValue(expectedLong));
    QCOMPARE(codec.encode("RTC::TimedLong", expectedLong, true, &error), marshal(timedLong));

    // A string before doubles: the alignment after it depends on its length.
    RTC::CameraImage image;
    image.tm.sec = 1;
    image.tm.nsec = 2;
    image.width = 640;
    image.height = 480;
    image.bpp = 24;
    image.format = CORBA::string_dup("rgb");
    image.fDiv = 0.5;
    image.pixels.length(5);
    for (CORBA::ULong i = 0; i < 5; ++i)
        image.pixels[i] = CORBA::Octet(250 + i);
    const QJsonObject expectedImage = json(R"({"tm":{"sec":1,"nsec":2},"width":640,"height":480,"bpp":24,"format":"rgb","fDiv":0.5,"pixels":[250,251,252,253,254]})");
    QCOMPARE(codec.decode("RTC::CameraImage", marshal(image), true, &error), QJsonValue(expectedImage));
    QCOMPARE(codec.encode("RTC::CameraImage", expectedImage, true, &error), marshal(image));

    // Enums, nested structs, unsigned members and a sequence of structs.
    RTC::GPSData gps {};
    gps.timeFromGPS.sec = 4000000000u;
    gps.timeFromGPS.msec = 999;
    gps.latitude = 35.6;
    gps.heading = -1.25;
    gps.numSatellites = 9;
    gps.fixType = RTC::GPS_FIX_DGPS;
    const QJsonValue gpsValue = codec.decode("RTC::GPSData", marshal(gps), true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(gpsValue["fixType"].toString(), QString("GPS_FIX_DGPS"));
    QCOMPARE(gpsValue["timeFromGPS"]["sec"].toInteger(), 4000000000LL);
    QVERIFY(sameSample(codec, "RTC::GPSData", codec.encode("RTC::GPSData", gpsValue, true, &error), marshal(gps)));

    RTC::ActArrayState actuators;
    actuators.tm.sec = 3;
    actuators.tm.nsec = 0;
    actuators.actuators.length(2);
    actuators.actuators[0] = {1.0, 2.0, 3.0, 4.0, RTC::ActArrayActuatorStatus(1)};
    actuators.actuators[1] = {-1.0, -2.0, -3.0, -4.0, RTC::ActArrayActuatorStatus(0)};
    const QJsonValue actuatorValue = codec.decode("RTC::ActArrayState", marshal(actuators), true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(actuatorValue["actuators"].toArray().size(), 2);
    QCOMPARE(actuatorValue["actuators"][1]["current"].toDouble(), -4.0);
    QVERIFY(sameSample(codec, "RTC::ActArrayState", codec.encode("RTC::ActArrayState", actuatorValue, true, &error),
                       marshal(actuators)));

    RTC::TimedPose2D pose;
    pose.tm.sec = 7;
    pose.tm.nsec = 8;
    pose.data.position.x = 1.5;
    pose.data.position.y = -2.5;
    pose.data.heading = 3.14;
    const QJsonValue poseValue = codec.decode("RTC::TimedPose2D", marshal(pose), true, &error);
    QCOMPARE(poseValue["data"]["position"]["y"].toDouble(), -2.5);
    QVERIFY(sameSample(codec, "RTC::TimedPose2D", codec.encode("RTC::TimedPose2D", poseValue, true, &error),
                       marshal(pose)));

    QCOMPARE(codec.decode("RTC::TimedString", marshal(RTC::TimedString {{0, 0}, "x"}), true, &error)["data"]
                 .toString(),
             QString("x"));
    QVERIFY2(error.isEmpty(), qPrintable(error));
}

void TestCdrCodec::wideCharactersMatchOmniOrb_data()
{
    QTest::addColumn<bool>("littleEndian");
    QTest::newRow("little-endian") << true;
    QTest::newRow("big-endian") << false;
}

void TestCdrCodec::wideCharactersMatchOmniOrb()
{
    // omniORB writes a wchar as big-endian UTF-16 after its length octet, a wstring in the machine's
    // order after a byte-order mark; it reads UTF-16 without a mark as big-endian.
    QFETCH(bool, littleEndian);
    const CdrCodec codec(m_library.model());
    QString error;
    const auto theirs = [littleEndian](const auto &value) {
        cdrMemoryStream stream;
        stream.setByteSwapFlag(littleEndian);
        value >>= stream;
        return QByteArray(static_cast<const char *>(stream.bufPtr()), int(stream.bufSize()));
    };
    const RTC::TimedWChar wchar{{5, 6}, CORBA::WChar(0x3042)};
    const QJsonObject wcharValue = json(R"({"tm":{"sec":5,"nsec":6},"data":"\u3042"})");
    QCOMPARE(codec.decode("RTC::TimedWChar", theirs(wchar), littleEndian, &error), QJsonValue(wcharValue));
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(codec.encode("RTC::TimedWChar", wcharValue, littleEndian, &error), theirs(wchar));

    RTC::TimedWString wstring;
    wstring.tm = {7, 8};
    wstring.data = CORBA::wstring_dup(L"h\u3042!"); // the member adopts it
    const QJsonObject wstringValue = json(R"({"tm":{"sec":7,"nsec":8},"data":"h\u3042!"})");
    QCOMPARE(codec.decode("RTC::TimedWString", theirs(wstring), littleEndian, &error), QJsonValue(wstringValue));
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QByteArray ours = codec.encode("RTC::TimedWString", wstringValue, littleEndian, &error);
    cdrMemoryStream stream;
    stream.setByteSwapFlag(littleEndian);
    stream.put_octet_array(reinterpret_cast<const CORBA::Octet *>(ours.constData()), CORBA::ULong(ours.size()));
    RTC::TimedWString decoded;
    decoded <<= stream;
    QCOMPARE(QString::fromWCharArray(decoded.data.in()), QStringLiteral("h\u3042!"));
    QCOMPARE(decoded.tm.nsec, CORBA::ULong(8));
}

void TestCdrCodec::anysMatchOmniOrb_data()
{
    QTest::addColumn<int>("which");
    QTest::addColumn<QString>("value");
    QTest::newRow("long") << 0 << R"({"name":"n","value":{"type":"long","value":-5}})";
    QTest::newRow("double") << 1 << R"({"name":"n","value":{"type":"double","value":2.5}})";
    QTest::newRow("string") << 2 << R"({"name":"n","value":{"type":"string","value":"corba_cdr"}})";
    QTest::newRow("boolean") << 3 << R"({"name":"n","value":{"type":"boolean","value":true}})";
    QTest::newRow("wstring") << 4 << R"({"name":"n","value":{"type":"wstring","value":"h\u3042"}})";
    QTest::newRow("empty") << 5 << R"({"name":"n","value":{"type":"null","value":null}})";
    QTest::newRow("nil object reference") << 6 << R"({"name":"n","value":{"type":"Object","value":null}})";
}

void TestCdrCodec::anysMatchOmniOrb()
{
    // SDOPackage::NameValue (NVLists' element): an any holding each kind the codec carries.
    QFETCH(int, which);
    QFETCH(QString, value);
    SDOPackage::NameValue nv;
    nv.name = "n";
    switch (which) {
    case 0: nv.value <<= CORBA::Long(-5); break;
    case 1: nv.value <<= CORBA::Double(2.5); break;
    case 2: nv.value <<= "corba_cdr"; break;
    case 3: nv.value <<= CORBA::Any::from_boolean(true); break;
    case 4: nv.value <<= L"h\u3042"; break;
    case 6: nv.value <<= CORBA::Object::_nil(); break;
    default: break;
    }
    const CdrCodec codec(m_library.model());
    QString error;
    const QJsonObject expected = QJsonDocument::fromJson(value.toUtf8()).object();
    QCOMPARE(codec.decode("SDOPackage::NameValue", marshal(nv), true, &error), QJsonValue(expected));
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QByteArray ours = codec.encode("SDOPackage::NameValue", expected, true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    if (which != 4) {
        QVERIFY(sameSample(codec, "SDOPackage::NameValue", ours, marshal(nv)));
        return;
    }
    // omniORB marks its wide strings' byte order, which GIOP 1.2 leaves out: it reads ours back.
    cdrMemoryStream stream;
    stream.put_octet_array(reinterpret_cast<const CORBA::Octet *>(ours.constData()), CORBA::ULong(ours.size()));
    SDOPackage::NameValue decoded;
    decoded <<= stream;
    const CORBA::WChar *text = nullptr;
    QVERIFY(decoded.value >>= text);
    QCOMPARE(QString::fromWCharArray(text), QStringLiteral("h\u3042"));
}

namespace {

/// The anys of constructed types omniORB's stubs make, by row of constructedAnysMatchOmniOrb.
const QList<std::function<void(CORBA::Any &)>> constructedAnys{
    [](CORBA::Any &a) { a <<= RTC::Time{1, 2}; },
    [](CORBA::Any &a) { a <<= RTC::TimedLong{{3, 4}, 5}; },
    [](CORBA::Any &a) { a <<= RTC::RTC_ERROR; },
    [](CORBA::Any &a) {
        SDOPackage::Numeric numeric;
        numeric.long_value(7);
        a <<= numeric;
    },
    [](CORBA::Any &a) {
        SDOPackage::NVList list;
        list.length(1);
        list[0].name = "k";
        list[0].value <<= CORBA::Long(1);
        a <<= list;
    },
    [](CORBA::Any &a) {
        RTC::TimedLongSeq sample;
        sample.tm = {0, 9};
        sample.data.length(2);
        sample.data[0] = 1;
        sample.data[1] = -2;
        a <<= sample;
    },
    [](CORBA::Any &a) { a <<= RTC::_tc_TimedLong; },
    [](CORBA::Any &a) {
        CORBA::Any inner;
        inner <<= CORBA::Long(5);
        a <<= inner;
    },
    [](CORBA::Any &a) { a <<= RTC::RTObject::_nil(); },
};

/// What omniORB makes of @p bytes (a NameValue in CDR), marshalled again.
QByteArray throughOmniOrb(const QByteArray &bytes, CORBA::TypeCode_ptr expectedType)
{
    cdrMemoryStream stream;
    stream.put_octet_array(reinterpret_cast<const CORBA::Octet *>(bytes.constData()), CORBA::ULong(bytes.size()));
    SDOPackage::NameValue read;
    read <<= stream;
    if (!read.value.type()->equal(expectedType))
        return {};
    return marshal(read);
}

} // namespace

void TestCdrCodec::constructedAnysMatchOmniOrb_data()
{
    QTest::addColumn<int>("which");
    QTest::addColumn<QString>("value");
    QTest::newRow("struct") << 0 << R"({"type":"RTC::Time","value":{"sec":1,"nsec":2}})";
    QTest::newRow("nested struct") << 1 << R"({"type":"RTC::TimedLong","value":{"tm":{"sec":3,"nsec":4},"data":5}})";
    QTest::newRow("enum") << 2 << R"({"type":"RTC::ReturnCode_t","value":"RTC_ERROR"})";
    QTest::newRow("union") << 3 << R"({"type":"SDOPackage::Numeric","value":{"_d":"LONG_TYPE","long_value":7}})";
    QTest::newRow("typedef of a sequence of anys")
        << 4 << R"({"type":"SDOPackage::NVList","value":[{"name":"k","value":{"type":"long","value":1}}]})";
    QTest::newRow("struct with a sequence")
        << 5 << R"({"type":"RTC::TimedLongSeq","value":{"tm":{"sec":0,"nsec":9},"data":[1,-2]}})";
    QTest::newRow("TypeCode") << 6 << R"({"type":"TypeCode","value":"RTC::TimedLong"})";
    QTest::newRow("any") << 7 << R"({"type":"any","value":{"type":"long","value":5}})";
    QTest::newRow("reference of an interface") << 8 << R"({"type":"RTC::RTObject","value":null})";
}

void TestCdrCodec::constructedAnysMatchOmniOrb()
{
    // An any in SDOPackage::NameValue holding what omniORB's stubs put into one; ours has the same
    // size and the same value, and omniORB reads ours back as the same type and value.
    QFETCH(int, which);
    QFETCH(QString, value);
    SDOPackage::NameValue nv;
    nv.name = "n";
    constructedAnys.at(which)(nv.value);
    const QJsonObject expected{{"name", "n"}, {"value", QJsonDocument::fromJson(value.toUtf8()).object()}};
    const CdrCodec codec(m_library.model());
    QString error;
    QCOMPARE(codec.decode("SDOPackage::NameValue", marshal(nv), true, &error), QJsonValue(expected));
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QByteArray ours = codec.encode("SDOPackage::NameValue", expected, true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(sameSample(codec, "SDOPackage::NameValue", ours, marshal(nv)));
    QVERIFY(sameSample(codec, "SDOPackage::NameValue", throughOmniOrb(ours, nv.value.type()), marshal(nv)));
    // Big-endian too (omniORB reads either byte order).
    const QByteArray big = codec.encode("SDOPackage::NameValue", expected, false, &error);
    QCOMPARE(codec.decode("SDOPackage::NameValue", big, false, &error), QJsonValue(expected));
    QVERIFY2(error.isEmpty(), qPrintable(error));
}

void TestCdrCodec::namedTypesRepeatedInATypeCodeAreIndirections()
{
    // RangerGeometry holds a Geometry3D and a sequence of them: omniORB writes Geometry3D's TypeCode
    // once and points to it the second time; so does the codec.
    RTC::RangerGeometry geometry{};
    geometry.geometry.size = {1, 2, 3};
    geometry.elementGeometries.length(1);
    geometry.elementGeometries[0].pose.position = {4, 5, 6};
    SDOPackage::NameValue nv;
    nv.name = "n";
    nv.value <<= geometry;
    const CdrCodec codec(m_library.model());
    QString error;
    const QJsonValue decoded = codec.decode("SDOPackage::NameValue", marshal(nv), true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(decoded["value"]["type"].toString(), QString("RTC::RangerGeometry"));
    QCOMPARE(decoded["value"]["value"]["elementGeometries"][0]["pose"]["position"]["y"].toDouble(), 5.0);
    const QByteArray ours = codec.encode("SDOPackage::NameValue", decoded, true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(sameSample(codec, "SDOPackage::NameValue", ours, marshal(nv)));
    QVERIFY(sameSample(codec, "SDOPackage::NameValue", throughOmniOrb(ours, nv.value.type()), marshal(nv)));
}

void TestCdrCodec::typeCodeValuesMatchOmniOrb()
{
    // SDOPackage::Parameter names a configuration parameter's type with a TypeCode.
    SDOPackage::Parameter parameter;
    parameter.name = "gain";
    parameter.type = CORBA::TypeCode::_duplicate(RTC::_tc_TimedDoubleSeq);
    SDOPackage::IntervalType interval;
    interval.min.long_value(0);
    interval.max.long_value(10);
    interval.min_inclusive = interval.max_inclusive = true;
    interval.step.long_value(1);
    parameter.allowed_values.allowed_interval(interval);
    const CdrCodec codec(m_library.model());
    QString error;
    const QJsonValue decoded = codec.decode("SDOPackage::Parameter", marshal(parameter), true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(decoded["type"].toString(), QString("RTC::TimedDoubleSeq"));
    const QByteArray ours = codec.encode("SDOPackage::Parameter", decoded, true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(sameSample(codec, "SDOPackage::Parameter", ours, marshal(parameter)));
    cdrMemoryStream stream;
    stream.put_octet_array(reinterpret_cast<const CORBA::Octet *>(ours.constData()), CORBA::ULong(ours.size()));
    SDOPackage::Parameter read;
    read <<= stream;
    QVERIFY(read.type->equal(RTC::_tc_TimedDoubleSeq));
    // Sequences, strings with a bound and arrays by their text.
    for (const char *text : {"sequence<RTC::Time>", "string<8>", "sequence<long, 4>", "double[2][3]", "wstring"}) {
        const QJsonObject value{{"name", "p"}, {"type", text}, {"allowed_values", decoded["allowed_values"]}};
        const QByteArray bytes = codec.encode("SDOPackage::Parameter", value, true, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(codec.decode("SDOPackage::Parameter", bytes, true, &error), QJsonValue(value));
    }
}

void TestCdrCodec::anyOfAnUndeclaredTypeIsRefused()
{
    SDOPackage::NameValue nv;
    nv.name = "n";
    nv.value <<= CosNaming::NameComponent{"a", "b"};
    const CdrCodec codec(m_library.model());
    QString error;
    QVERIFY(codec.decode("SDOPackage::NameValue", marshal(nv), true, &error).isUndefined());
    QVERIFY2(error.contains("value: an any of type IDL:omg.org/CosNaming/NameComponent:1.0, which the IDL files do not declare"),
             qPrintable(error));
    QVERIFY(codec.encode("SDOPackage::NameValue", json(R"({"name":"n","value":{"type":"Acme::Thing","value":{}}})"), true,
                         &error).isEmpty());
    QVERIFY2(error.contains("value: type 'Acme::Thing' is not declared in the IDL files"), qPrintable(error));
    QVERIFY(codec.encode("SDOPackage::NameValue", json(R"({"name":"n","value":{"type":"sequence<","value":{}}})"), true,
                         &error).isEmpty());
    QVERIFY2(error.contains("'sequence<' is not a type"), qPrintable(error));
}

void TestCdrCodec::unionsMatchOmniOrb()
{
    const CdrCodec codec(m_library.model());
    QString error;
    SDOPackage::Numeric numeric;
    numeric.double_value(2.5);
    const QJsonObject numericValue = json(R"({"_d":"DOUBLE_TYPE","double_value":2.5})");
    QCOMPARE(codec.decode("SDOPackage::Numeric", marshal(numeric), true, &error), QJsonValue(numericValue));
    QVERIFY(sameSample(codec, "SDOPackage::Numeric", codec.encode("SDOPackage::Numeric", numericValue, true, &error),
                       marshal(numeric)));
    QVERIFY2(error.isEmpty(), qPrintable(error));
    // Unions as struct members; the discriminator picks the member written.
    SDOPackage::RangeType range;
    range.min.short_value(-3);
    range.max.long_value(70000);
    range.min_inclusive = true;
    range.max_inclusive = false;
    const QJsonObject rangeValue = json(R"({"min":{"_d":"SHORT_TYPE","short_value":-3},)"
                                        R"("max":{"_d":"LONG_TYPE","long_value":70000},)"
                                        R"("min_inclusive":true,"max_inclusive":false})");
    QCOMPARE(codec.decode("SDOPackage::RangeType", marshal(range), true, &error), QJsonValue(rangeValue));
    QVERIFY(sameSample(codec, "SDOPackage::RangeType", codec.encode("SDOPackage::RangeType", rangeValue, true, &error),
                       marshal(range)));
    // No discriminator given: the first case.
    QCOMPARE(codec.decode("SDOPackage::Numeric", codec.encode("SDOPackage::Numeric", QJsonObject(), true, &error), true,
                          &error),
             QJsonValue(json(R"({"_d":"SHORT_TYPE","short_value":0})")));
    QVERIFY2(error.isEmpty(), qPrintable(error));
}

void TestCdrCodec::objectReferencesMatchOmniOrb()
{
    // A port profile with nil references, and one holding a reference to a live object of this ORB.
    const CdrCodec codec(m_library.model());
    QString error;
    RTC::PortProfile nilProfile;
    nilProfile.name = CORBA::string_dup("in");
    const QJsonValue nilValue = codec.decode("RTC::PortProfile", marshal(nilProfile), true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(nilValue["port_ref"].isNull() && nilValue["owner"].isNull());
    QVERIFY(sameSample(codec, "RTC::PortProfile", codec.encode("RTC::PortProfile", nilValue, true, &error),
                       marshal(nilProfile)));

    RTC::PortProfile profile;
    profile.name = CORBA::string_dup("out");
    CORBA::Object_var object = m_orb->string_to_object("corbaloc::127.0.0.1:2809/NameService");
    profile.owner = RTC::RTObject::_unchecked_narrow(object);
    const QByteArray theirs = marshal(profile);
    const QJsonValue value = codec.decode("RTC::PortProfile", theirs, true, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(value["owner"]["profiles"].toArray().size(), 1);
    const QByteArray ours = codec.encode("RTC::PortProfile", value, true, &error);
    QVERIFY(sameSample(codec, "RTC::PortProfile", ours, theirs));
    // omniORB reads the reference we wrote as the object it wrote.
    cdrMemoryStream stream;
    stream.put_octet_array(reinterpret_cast<const CORBA::Octet *>(ours.constData()), CORBA::ULong(ours.size()));
    RTC::PortProfile decoded;
    decoded <<= stream;
    QVERIFY(decoded.owner->_is_equivalent(object));
}

void TestCdrCodec::bigEndianRoundTrip()
{
    const CdrCodec codec(m_library.model());
    QString error;
    const QJsonObject value = json(R"({"tm":{"sec":1,"nsec":2},"data":[1.5,-2,"NaN","Infinity"]})");
    const QByteArray big = codec.encode("RTC::TimedDoubleSeq", value, false, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(big.left(4), QByteArray::fromHex("00000001"));
    QCOMPARE(codec.decode("RTC::TimedDoubleSeq", big, false, &error), QJsonValue(value));
    QVERIFY(codec.decode("RTC::TimedDoubleSeq", big, true, &error).isUndefined()); // wrong order
    QVERIFY(!error.isEmpty());
}

void TestCdrCodec::malformedSamplesAreReported_data()
{
    QTest::addColumn<QString>("type");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected");
    QTest::newRow("empty") << "RTC::TimedLong" << QByteArray() << "tm.sec: the sample ends early";
    QTest::newRow("short") << "RTC::TimedLong" << QByteArray(10, '\0') << ".data: the sample ends early";
    QTest::newRow("huge sequence") << "RTC::TimedLongSeq" << QByteArray::fromHex("0100000002000000ffffff7f")
                                   << ".data: sequence of 2147483647 elements where 0 bytes remain";
    QTest::newRow("string without end")
        << "RTC::TimedString" << QByteArray::fromHex("0000000000000000ffff0000") << ".data: string of 65535 bytes";
    QTest::newRow("enum out of range")
        << "RTC::Actuator" << QByteArray(32, '\0') + QByteArray::fromHex("09000000")
        << ".status: RTC::ActArrayActuatorStatus has no enumerator 9";
    QTest::newRow("left over") << "RTC::TimedLong" << QByteArray(32, '\0') << "20 bytes left over";
    QTest::newRow("unknown type") << "Nowhere::Thing" << QByteArray(4, '\0') << "not declared";
}

void TestCdrCodec::malformedSamplesAreReported()
{
    QFETCH(QString, type);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    const CdrCodec codec(m_library.model());
    QString error;
    QVERIFY(codec.decode(type, bytes, true, &error).isUndefined());
    QVERIFY2(error.contains(expected), qPrintable(error));
}

void TestCdrCodec::badValuesAreReported_data()
{
    QTest::addColumn<QString>("type");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown member") << "RTC::TimedLong" << R"({"dat":1})" << "has no member 'dat'";
    QTest::newRow("out of range") << "RTC::TimedShort" << R"({"data":70000})" << ".data: 70000 is not a whole number";
    QTest::newRow("fraction") << "RTC::TimedLong" << R"({"data":1.5})" << "not a whole number";
    QTest::newRow("text for number") << "RTC::TimedDouble" << R"({"data":"x"})" << "'x' is not a number";
    QTest::newRow("enum") << "RTC::Actuator" << R"({"status":"BROKEN"})" << "'BROKEN' is none of";
    QTest::newRow("nested") << "RTC::TimedLongSeq" << R"({"data":[1,"a"]})" << ".data[1]: 'a' is not a number";
}

void TestCdrCodec::badValuesAreReported()
{
    QFETCH(QString, type);
    QFETCH(QString, value);
    QFETCH(QString, expected);
    const CdrCodec codec(m_library.model());
    QString error;
    QVERIFY(codec.encode(type, QJsonDocument::fromJson(value.toUtf8()).object(), true, &error).isEmpty());
    QVERIFY2(error.contains(expected), qPrintable(error));
}

void TestCdrCodec::commandLineValues()
{
    const CdrCodec codec(m_library.model());
    QString error;
    QCOMPARE(codec.parseArgument("RTC::TimedLong", "42", &error), QJsonValue(json(R"({"data":42})")));
    QCOMPARE(codec.parseArgument("RTC::TimedString", "hello world", &error),
             QJsonValue(json(R"({"data":"hello world"})")));
    QCOMPARE(codec.parseArgument("RTC::TimedString", "\"quoted\"", &error), QJsonValue(json(R"({"data":"quoted"})")));
    QCOMPARE(codec.parseArgument("RTC::TimedDoubleSeq", "[1, 2.5]", &error),
             QJsonValue(json(R"({"data":[1,2.5]})")));
    QCOMPARE(codec.parseArgument("RTC::TimedLong", R"({"tm":{"sec":1,"nsec":0},"data":3})", &error),
             QJsonValue(json(R"({"tm":{"sec":1,"nsec":0},"data":3})")));
    QVERIFY(error.isEmpty());
    QVERIFY(codec.parseArgument("RTC::TimedLong", "forty-two", &error).isUndefined());
    QVERIFY2(error.contains("not a value for RTC::TimedLong.data"), qPrintable(error));
    QVERIFY(codec.parseArgument("RTC::CameraImage", "1", &error).isUndefined());
    QVERIFY2(error.contains("give them as a JSON object"), qPrintable(error));

    // A timed type's timestamp defaults to the time of encoding.
    const QByteArray bytes = codec.encode("RTC::TimedLong", json(R"({"data":1})"), true, &error);
    const qint64 sec = codec.decode("RTC::TimedLong", bytes, true, &error)["tm"]["sec"].toInteger();
    QVERIFY(qAbs(sec - QDateTime::currentSecsSinceEpoch()) < 5);
}

void TestCdrCodec::textAndJsonForms()
{
    const CdrCodec codec(m_library.model());
    const QJsonObject pose = json(R"({"tm":{"sec":7,"nsec":8},"data":{"position":{"x":1.5,"y":-2},"heading":0.25}})");
    QCOMPARE(codec.toText("RTC::TimedPose2D", pose),
             QString("[7.000000008] data={position={x=1.5, y=-2}, heading=0.25}"));
    QCOMPARE(codec.toJson("RTC::TimedPose2D", pose),
             QString(R"({"tm":{"sec":7,"nsec":8},"data":{"position":{"x":1.5,"y":-2},"heading":0.25}})"));
    QCOMPARE(codec.toText("RTC::TimedString",
                          json("{\"tm\":{\"sec\":1,\"nsec\":0},\"data\":\"a \\\"b\\\"\"}")),
             QString("[1.000000000] data=\"a \\\"b\\\"\""));
    QCOMPARE(codec.toText("RTC::TimedLongSeq", json(R"({"tm":{"sec":1,"nsec":0},"data":[1,2,3]})")),
             QString("[1.000000000] data=[1, 2, 3]"));
    QCOMPARE(codec.toText("RTC::Point2D", json(R"({"x":1,"y":2})")), QString("{x=1, y=2}"));
}

QTEST_GUILESS_MAIN(TestCdrCodec)
#include "tst_cdrcodec.moc"

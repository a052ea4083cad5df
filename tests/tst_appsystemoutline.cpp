// SPDX-License-Identifier: MIT
// The System Editor's outline model: structure, roles, and QAbstractItemModelTester.
#include "documentloader.h"
#include "rtsdocument.h"
#include "systemoutlinemodel.h"

#include <QAbstractItemModelTester>
#include <QTest>

using namespace Studio;
using Kind = SystemOutlineModel::NodeKind;

namespace {

std::unique_ptr<RtsDocument> loadSystem(const QString &name)
{
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> document
        = loadDocument((RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/app/")) + name, &diagnostics);
    if (!document || !qobject_cast<RtsDocument *>(document.get()))
        return nullptr;
    return std::unique_ptr<RtsDocument>(static_cast<RtsDocument *>(document.release()));
}

QString text(const QAbstractItemModel &model, const QModelIndex &index, int column = 0)
{
    return model.index(index.row(), column, index.parent()).data().toString();
}

Kind kindOf(const QModelIndex &index)
{
    return Kind(index.data(SystemOutlineModel::NodeKindRole).toInt());
}

} // namespace

class TestAppSystemOutline : public QObject
{
    Q_OBJECT

private slots:
    void passesModelTester_data();
    void passesModelTester();
    void listsComponentsWithPorts();
    void listsConnectorsWithEnds();
    void findsItemsByStableId();
    void emptySystemHasEmptyGroups();
    void rejectsForeignAndOutOfRangeIndexes();
};

void TestAppSystemOutline::passesModelTester_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("xml") << QStringLiteral("system.xml");
    QTest::newRow("yaml") << QStringLiteral("system.yaml");
}

void TestAppSystemOutline::passesModelTester()
{
    QFETCH(QString, file);
    std::unique_ptr<RtsDocument> document = loadSystem(file);
    QVERIFY(document);
    SystemOutlineModel model(document.get());
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.columnCount(), 2);
    QVERIFY(model.rowCount(model.index(0, 0)) > 0);
}

void TestAppSystemOutline::listsComponentsWithPorts()
{
    std::unique_ptr<RtsDocument> document = loadSystem(QStringLiteral("system.xml"));
    QVERIFY(document);
    SystemOutlineModel model(document.get());
    const QModelIndex components = model.index(0, 0);
    QCOMPARE(kindOf(components), Kind::ComponentGroup);
    QCOMPARE(text(model, components), QStringLiteral("Components"));
    QCOMPARE(text(model, components, 1), QStringLiteral("2 component(s)"));
    QCOMPARE(model.rowCount(components), 2);

    const QModelIndex filter = model.index(1, 0, components);
    QCOMPARE(kindOf(filter), Kind::Component);
    QCOMPARE(text(model, filter), QStringLiteral("RangeFilter0"));
    QCOMPARE(text(model, filter, 1), QStringLiteral("RTC:ExampleVendor:Sensor:RangeFilter:2.1.0"));
    QCOMPARE(
        filter.data(Qt::ToolTipRole).toString(),
        QStringLiteral("RTC:ExampleVendor:Sensor:RangeFilter:2.1.0\nlocalhost/RangeFilter0.rtc"));
    QCOMPARE(filter.data(SystemOutlineModel::InstanceNameRole).toString(),
             QStringLiteral("RangeFilter0"));
    QVERIFY(!filter.data(Qt::DecorationRole).value<QIcon>().isNull());

    QCOMPARE(model.rowCount(filter), 3);
    const QStringList expectedPorts
        = {QStringLiteral("RangeFilter0.scan"), QStringLiteral("RangeFilter0.filtered"),
           QStringLiteral("RangeFilter0.scanner")};
    const QList<Kind> expectedKinds = {Kind::DataPort, Kind::DataPort, Kind::ServicePort};
    for (int row = 0; row < 3; ++row) {
        const QModelIndex port = model.index(row, 0, filter);
        QCOMPARE(text(model, port), expectedPorts.at(row));
        QCOMPARE(kindOf(port), expectedKinds.at(row));
        QCOMPARE(port.data(SystemOutlineModel::PortNameRole).toString(), expectedPorts.at(row));
        QCOMPARE(port.data(SystemOutlineModel::InstanceNameRole).toString(),
                 QStringLiteral("RangeFilter0"));
        QCOMPARE(model.parent(port), filter);
        QCOMPARE(model.rowCount(port), 0);
    }
}

void TestAppSystemOutline::listsConnectorsWithEnds()
{
    std::unique_ptr<RtsDocument> document = loadSystem(QStringLiteral("system.xml"));
    QVERIFY(document);
    SystemOutlineModel model(document.get());
    const QModelIndex connectors = model.index(1, 0);
    QCOMPARE(kindOf(connectors), Kind::ConnectorGroup);
    QCOMPARE(model.rowCount(connectors), 2);

    const QModelIndex data = model.index(0, 0, connectors);
    QCOMPARE(kindOf(data), Kind::DataConnector);
    QCOMPARE(text(model, data), QStringLiteral("scan_scan"));
    QCOMPARE(text(model, data, 1), QStringLiteral("data, RTC::RangeData"));
    QCOMPARE(data.data(SystemOutlineModel::ConnectorIdRole).toString(), QStringLiteral("c1-scan"));
    QCOMPARE(model.rowCount(data), 2);
    const QModelIndex source = model.index(0, 0, data);
    const QModelIndex target = model.index(1, 0, data);
    QCOMPARE(kindOf(source), Kind::ConnectorSource);
    QCOMPARE(kindOf(target), Kind::ConnectorTarget);
    QCOMPARE(text(model, source, 1), QStringLiteral("Scanner0 · Scanner0.scan"));
    QCOMPARE(text(model, target, 1), QStringLiteral("RangeFilter0 · RangeFilter0.scan"));
    QCOMPARE(target.data(SystemOutlineModel::PortNameRole).toString(),
             QStringLiteral("RangeFilter0.scan"));

    const QModelIndex service = model.index(1, 0, connectors);
    QCOMPARE(kindOf(service), Kind::ServiceConnector);
    QCOMPARE(text(model, service), QStringLiteral("scanner_control"));
    QCOMPARE(text(model, model.index(0, 0, service), 1),
             QStringLiteral("RangeFilter0 · RangeFilter0.scanner"));
}

void TestAppSystemOutline::findsItemsByStableId()
{
    std::unique_ptr<RtsDocument> document = loadSystem(QStringLiteral("system.yaml"));
    QVERIFY(document);
    SystemOutlineModel model(document.get());
    const QModelIndex base = model.componentIndex(QStringLiteral("Base0"));
    QVERIFY(base.isValid());
    QCOMPARE(base.data().toString(), QStringLiteral("Base0"));
    QCOMPARE(base.row(), 1);
    QVERIFY(!model.componentIndex(QStringLiteral("Nobody")).isValid());

    const QModelIndex connector = model.connectorIndex(QStringLiteral("c1-velocity"));
    QVERIFY(connector.isValid());
    QCOMPARE(connector.data().toString(), QStringLiteral("velocity_velocity"));
    QVERIFY(!model.connectorIndex(QStringLiteral("c9")).isValid());
}

void TestAppSystemOutline::emptySystemHasEmptyGroups()
{
    RtsDocument document(Profile::RtsProfile::createNew(QStringLiteral("V"), QStringLiteral("S"),
                                                        QStringLiteral("1")));
    SystemOutlineModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.rowCount(model.index(0, 0)), 0);
    QCOMPARE(model.rowCount(model.index(1, 0)), 0);
    QCOMPARE(model.index(1, 1).data().toString(), QStringLiteral("0 connector(s)"));
    QCOMPARE(model.headerData(0, Qt::Horizontal).toString(), QStringLiteral("Name"));
    QCOMPARE(model.headerData(1, Qt::Horizontal).toString(), QStringLiteral("Details"));
}

void TestAppSystemOutline::rejectsForeignAndOutOfRangeIndexes()
{
    std::unique_ptr<RtsDocument> document = loadSystem(QStringLiteral("system.xml"));
    QVERIFY(document);
    SystemOutlineModel model(document.get());
    QVERIFY(!model.index(2, 0).isValid());
    QVERIFY(!model.index(0, 2).isValid());
    QVERIFY(!model.index(-1, 0).isValid());
    QCOMPARE(model.rowCount(model.index(0, 1)), 0); // only column 0 has children

    SystemOutlineModel other(document.get());
    const QModelIndex foreign = other.index(0, 0);
    QCOMPARE(model.rowCount(foreign), 0);
    QVERIFY(!model.data(foreign).isValid());
}

QTEST_MAIN(TestAppSystemOutline)
#include "tst_appsystemoutline.moc"

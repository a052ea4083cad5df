// SPDX-License-Identifier: MIT
#include "autolayout.h"
#include "componentfactory.h"
#include "connectorcommands.h"

#include <QRectF>
#include <QTest>
#include <QUndoStack>

using namespace Profile;
using namespace SystemEditor;

namespace {

RtcProfile filter(int inputs, int outputs)
{
    RtcProfile rtc;
    rtc.basicInfo.name = "Filter";
    for (int i = 0; i < inputs; ++i) {
        RtcDataPort port;
        port.portType = "DataInPort";
        port.name = QStringLiteral("in%1").arg(i);
        port.type = "RTC::TimedLong";
        rtc.dataPorts << port;
    }
    for (int i = 0; i < outputs; ++i) {
        RtcDataPort port;
        port.portType = "DataOutPort";
        port.name = QStringLiteral("out%1").arg(i);
        port.type = "RTC::TimedLong";
        rtc.dataPorts << port;
    }
    return rtc;
}

void connect(SystemModel &model, const QString &from, const QString &fromPort, const QString &to,
             const QString &toPort)
{
    const ConnectorEnd source {from, from + "." + fromPort};
    const ConnectorEnd target {to, to + "." + toPort};
    model.addDataConnector(makeDataConnector(
        model, source, target, ConnectorSettings::defaults(source.portName, target.portName, "T")));
}

/// A pipeline listed backwards in the file, with a branch: Sink ← Mid ← Source → Side,
/// plus one component with no connection.
std::unique_ptr<SystemModel> pipeline()
{
    auto model = std::make_unique<SystemModel>();
    const QPointF here(0, 0); // all stacked on one spot: the worst start
    model->addComponent(componentFromRtcProfile(filter(1, 0), "Sink", "", here), filter(1, 0));
    model->addComponent(componentFromRtcProfile(filter(1, 1), "Mid", "", here), filter(1, 1));
    model->addComponent(componentFromRtcProfile(filter(0, 4), "Source", "", here), filter(0, 4));
    model->addComponent(componentFromRtcProfile(filter(1, 0), "Side", "", here), filter(1, 0));
    model->addComponent(componentFromRtcProfile(filter(0, 0), "Lonely", "", here), filter(0, 0));
    connect(*model, "Source", "out0", "Mid", "in0");
    connect(*model, "Mid", "out0", "Sink", "in0");
    connect(*model, "Source", "out1", "Side", "in0");
    return model;
}

} // namespace

class TestSeAutoLayout : public QObject
{
    Q_OBJECT

private slots:
    void leftToRightFollowsDataFlow();
    void noOverlaps();
    void appliedAsOneUndoableStep();
    void emptySystem();
};

void TestSeAutoLayout::leftToRightFollowsDataFlow()
{
    const auto model = pipeline();
    const QHash<QString, QPointF> positions = computeAutoLayout(*model);
    QCOMPARE(positions.size(), 5);
    QVERIFY(positions.value("Source").x() < positions.value("Mid").x());
    QVERIFY(positions.value("Mid").x() < positions.value("Sink").x());
    QVERIFY(positions.value("Source").x() < positions.value("Side").x());
    // The whole system starts at the origin.
    qreal left = 1e9;
    qreal top = 1e9;
    for (const QPointF &p : positions) {
        left = qMin(left, p.x());
        top = qMin(top, p.y());
    }
    QVERIFY(qAbs(left - 20) <= 1);
    QVERIFY(qAbs(top - 20) <= 1);
}

void TestSeAutoLayout::noOverlaps()
{
    const auto model = pipeline();
    const QHash<QString, QPointF> positions = computeAutoLayout(*model);
    QList<QRectF> boxes;
    for (auto it = positions.cbegin(); it != positions.cend(); ++it)
        boxes << QRectF(it.value(), componentSize(*model, it.key()));
    // Source has four ports on one side and is taller than the rest.
    QVERIFY(componentSize(*model, "Source").height() > componentSize(*model, "Sink").height());
    for (int i = 0; i < boxes.size(); ++i) {
        for (int j = i + 1; j < boxes.size(); ++j)
            QVERIFY2(!boxes.at(i).intersects(boxes.at(j)),
                     qPrintable(QStringLiteral("boxes %1 and %2 overlap").arg(i).arg(j)));
    }
}

void TestSeAutoLayout::appliedAsOneUndoableStep()
{
    const auto model = pipeline();
    const RtsProfile before = model->profile();
    QUndoStack stack;
    QUndoCommand *command = autoLayoutCommand(model.get());
    QVERIFY(command);
    QCOMPARE(command->text(), QStringLiteral("Auto Layout"));
    stack.push(command);
    const RtsProfile after = model->profile();
    QVERIFY(after != before);
    const QHash<QString, QPointF> expected = computeAutoLayout(*model);
    for (const QString &name : model->componentIds()) {
        QCOMPARE(model->layout(name).position, expected.value(name));
        // Positions are stored in rtsExt:Location.
        QCOMPARE(model->component(name)->layout->x,
                 QString::number(qRound(expected.value(name).x())));
    }
    stack.undo();
    QCOMPARE(model->profile(), before);
    stack.redo();
    QCOMPARE(model->profile(), after);
    QCOMPARE(stack.count(), 1);
}

void TestSeAutoLayout::emptySystem()
{
    SystemModel model;
    QVERIFY(computeAutoLayout(model).isEmpty());
    QVERIFY(!autoLayoutCommand(&model));
}

QTEST_GUILESS_MAIN(TestSeAutoLayout)
#include "tst_seautolayout.moc"

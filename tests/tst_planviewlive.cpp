// SPDX-License-Identifier: MIT
// The Plan view on live managers: an rtmanager on a free loopback port (told it has the lidar)
// and an address where nothing answers. The facts are read off the GUI thread; the answering
// manager gets a lane, the silent one is named in the status, and the plan uses the live facts.
#include "livesystem.h"
#include "orb.h"
#include "planscene.h"
#include "planview.h"
#include "profileio.h"
#include "systemmodel.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace SystemEditor;

class TestPlanViewLive : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void lanesFromLiveManagers();

private:
    LiveTest::LiveSystem m_live;
    quint16 m_port = 0;
};

void TestPlanViewLive::initTestCase()
{
    Corba::Orb::setCallTimeout(3000);
    m_port = LiveTest::freePort();
    QString error;
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, m_port,
                                 {QStringLiteral("naming.enable=NO"),
                                  QStringLiteral("node.devices=lidar0"),
                                  QStringLiteral("node.role=onboard")},
                                 &error),
             qPrintable(error));
}

void TestPlanViewLive::cleanupTestCase()
{
    m_live.stopAll();
}

void TestPlanViewLive::lanesFromLiveManagers()
{
    Profile::Diagnostics diagnostics;
    const auto robot = Profile::loadProfileFile(
        RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/planner/robot.xml"), &diagnostics);
    QVERIFY(robot && robot->rts);
    SystemModel model(*robot->rts);
    QUndoStack undo;
    PlanView view(&model, &undo);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QString live = QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_port);
    const QString silent = QStringLiteral("corbaloc::127.0.0.1:%1").arg(LiveTest::freePort());
    QSignalSpy planned(&view, &PlanView::planChanged);
    QElapsedTimer call;
    call.start();
    view.readFactsFromManagers({live, silent});
    // The GUI thread only started the reading.
    QVERIFY(call.elapsed() < 500);
    QVERIFY(view.isBusy());
    QVERIFY(planned.wait(30000));
    QCOMPARE(view.facts().size(), qsizetype(1));
    QCOMPARE(view.facts().first().name, live);
    QCOMPARE(view.facts().first().userFacts.value(QStringLiteral("devices")),
             QStringLiteral("lidar0"));
    QVERIFY2(view.statusText().contains(silent), qPrintable(view.statusText()));
    QCOMPARE(view.scene()->lanes().first().node, live);
    // One node: whatever is placed is there, and every explanation names it as the closest.
    const QList<PlanLane> &lanes = view.scene()->lanes();
    QVERIFY(lanes.size() == 1 || (lanes.size() == 2 && lanes.at(1).node.isEmpty()));
    for (const Planner::Placement &p : view.plan().placements)
        QCOMPARE(p.node, live);
    for (const Planner::Unmet &u : view.plan().unmet)
        QVERIFY(u.closestNode.isEmpty() || u.closestNode == live);
    QCOMPARE(view.plan().feasible, view.plan().unmet.isEmpty());
}

QTEST_MAIN(TestPlanViewLive)
#include "tst_planviewlive.moc"

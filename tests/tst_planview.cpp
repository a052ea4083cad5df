// SPDX-License-Identifier: MIT
// The Plan view (systemeditor/plan/): lanes built from a facts file and a system, a drag that
// pins a component (and undo that frees it), re-planning that moves the rest, unmet requirements
// in red, installs from a component repository, the dry run, and the Deploy button's signal.
#include "nativerepository.h"
#include "pincommand.h"
#include "plancarditem.h"
#include "planscene.h"
#include "planview.h"
#include "profileio.h"
#include "requirements.h"
#include "systemmodel.h"

#include <QAction>
#include <QFile>
#include <QGraphicsView>
#include <QListWidget>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>

using namespace SystemEditor;

namespace {

const QString Onboard = QStringLiteral("corbaloc::onboard:2810");
const QString Base = QStringLiteral("corbaloc::base:2810");
constexpr int PlanTimeoutMs = 30000;

QString dataFile(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/planner/")) + name;
}

std::optional<Profile::LoadedProfile> load(const QString &name)
{
    Profile::Diagnostics diagnostics;
    return Profile::loadProfileFile(dataFile(name), &diagnostics);
}

/// The lane (its node; empty: not placed) that shows @p instance, or "?" when none does.
QString laneOf(const PlanView &view, const QString &instance)
{
    for (const PlanLane &lane : view.scene()->lanes()) {
        for (const PlanCard &card : lane.cards) {
            if (card.instanceName == instance)
                return lane.node;
        }
    }
    return QStringLiteral("?");
}

const PlanCard *cardOf(const PlanView &view, const QString &instance)
{
    for (const PlanLane &lane : view.scene()->lanes()) {
        for (const PlanCard &card : lane.cards) {
            if (card.instanceName == instance)
                return &card;
        }
    }
    return nullptr;
}

QString describe(const PlanView &view)
{
    QStringList lines {view.statusText()};
    for (int i = 0; i < view.unmetList()->count(); ++i)
        lines << view.unmetList()->item(i)->text();
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestPlanView : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void lanesFromFactsFileAndSystem();
    void brokenFactsFileIsReported();
    void dragPinsAndUndoFrees();
    void dropOutsideAnotherLaneChangesNothing();
    void freeingUndoesToThePin();
    void cardMenuPinsHereAndFrees();
    void replanMovesTheRest();
    void unmetRequirementShownInRed();
    void pinIsKeptBySavingTheSystem();
    void dryRunListsWhatWouldHappen();
    void installsFromRepositoryShownInLanes();
    void deployWaitsForTheTransaction();
    void cancelDropsTheResult();

private:
    /// Opens @p facts and waits for the plan.
    bool planOn(const QString &facts);
    /// Drags the card of @p instance with the mouse and drops it in the lane of @p node.
    void drag(const QString &instance, int toLane);
    int laneIndex(const QString &node) const;

    std::unique_ptr<SystemModel> m_model;
    std::unique_ptr<QUndoStack> m_undo;
    std::unique_ptr<PlanView> m_view;
};

void TestPlanView::init()
{
    const auto robot = load(QStringLiteral("robot.xml"));
    const auto viewer = load(QStringLiteral("profiles/Viewer.xml"));
    QVERIFY(robot && robot->rts && viewer && viewer->rtc);
    m_model = std::make_unique<SystemModel>();
    m_model->setProfile(*robot->rts, {{QStringLiteral("Viewer0"), *viewer->rtc}});
    m_undo = std::make_unique<QUndoStack>();
    m_view = std::make_unique<PlanView>(m_model.get(), m_undo.get());
    m_view->resize(1000, 700);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
}

void TestPlanView::cleanup()
{
    m_view.reset();
    m_undo.reset();
    m_model.reset();
}

bool TestPlanView::planOn(const QString &facts)
{
    QSignalSpy planned(m_view.get(), &PlanView::planChanged);
    if (!m_view->openFactsFile(dataFile(facts)))
        return false;
    return planned.wait(PlanTimeoutMs) && !m_view->isBusy();
}

int TestPlanView::laneIndex(const QString &node) const
{
    const QList<PlanLane> &lanes = m_view->scene()->lanes();
    for (int l = 0; l < lanes.size(); ++l) {
        if (lanes.at(l).node == node)
            return l;
    }
    return -1;
}

void TestPlanView::drag(const QString &instance, int toLane)
{
    QGraphicsView *view = m_view->graphicsView();
    PlanCardItem *card = m_view->scene()->card(instance);
    QVERIFY(card);
    const QPoint from = view->mapFromScene(card->sceneBoundingRect().center());
    const QPoint to = view->mapFromScene(PlanScene::cardPosition(toLane, 0)
                                         + QPointF(PlanCardItem::Width / 2, 4));
    QTest::mousePress(view->viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(view->viewport(), (from + to) / 2);
    QTest::mouseMove(view->viewport(), to);
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, to);
}

void TestPlanView::lanesFromFactsFileAndSystem()
{
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    QVERIFY2(m_view->plan().feasible, qPrintable(describe(*m_view)));
    const QList<PlanLane> &lanes = m_view->scene()->lanes();
    QCOMPARE(lanes.size(), qsizetype(2));
    QCOMPARE(lanes.at(0).node, Onboard);
    QCOMPARE(lanes.at(1).node, Base);
    // The lidar's driver needs the onboard device; the Python viewer needs the base's Python;
    // the logger is pinned to the base by the system.
    QCOMPARE(laneOf(*m_view, QStringLiteral("Lidar0")), Onboard);
    QCOMPARE(laneOf(*m_view, QStringLiteral("Viewer0")), Base);
    QCOMPARE(laneOf(*m_view, QStringLiteral("Logger0")), Base);
    QVERIFY(cardOf(*m_view, QStringLiteral("Logger0"))->pinned);
    QVERIFY(!cardOf(*m_view, QStringLiteral("Lidar0"))->pinned);
    QCOMPARE(cardOf(*m_view, QStringLiteral("Ctrl0"))->process, QStringLiteral("Loop0"));
    // Nothing in red; the types without an RTC profile are noted.
    QVERIFY(m_view->unmetList()->count() > 0);
    for (int i = 0; i < m_view->unmetList()->count(); ++i) {
        QListWidgetItem *item = m_view->unmetList()->item(i);
        QVERIFY2(item->foreground() != QColor(200, 30, 30), qPrintable(item->text()));
        QVERIFY2(item->text().startsWith(QLatin1String("no RTC profile of ")),
                 qPrintable(item->text()));
    }
    // Every component has its card in the scene, where its lane says.
    for (const QString &instance : m_model->componentIds()) {
        PlanCardItem *item = m_view->scene()->card(instance);
        QVERIFY2(item, qPrintable(instance));
        QCOMPARE(m_view->scene()->laneAt(item->sceneBoundingRect().center()),
                 laneIndex(laneOf(*m_view, instance)));
    }
}

void TestPlanView::brokenFactsFileIsReported()
{
    QVERIFY(!m_view->openFactsFile(dataFile(QStringLiteral("nodes-broken.yaml"))));
    QVERIFY2(m_view->statusText().contains(QLatin1String("nodes-broken.yaml")),
             qPrintable(m_view->statusText()));
    QVERIFY(m_view->facts().isEmpty());
    QVERIFY(!m_view->isBusy());
}

void TestPlanView::dragPinsAndUndoFrees()
{
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Onboard);
    drag(QStringLiteral("Filter0"), laneIndex(Base));
    QTRY_COMPARE(pinnedNode(*m_model, QStringLiteral("Filter0")), Base);
    QCOMPARE(m_undo->count(), 1);
    // Shown where it is pinned at once, before any re-planning; the plan is out of date.
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Base);
    QVERIFY(cardOf(*m_view, QStringLiteral("Filter0"))->pinned);
    QVERIFY(m_view->isOutOfDate());
    m_undo->undo();
    QCOMPARE(pinnedNode(*m_model, QStringLiteral("Filter0")), QString());
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Onboard);
    QVERIFY(!cardOf(*m_view, QStringLiteral("Filter0"))->pinned);
    m_undo->redo();
    QCOMPARE(pinnedNode(*m_model, QStringLiteral("Filter0")), Base);
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Base);
}

void TestPlanView::dropOutsideAnotherLaneChangesNothing()
{
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    drag(QStringLiteral("Filter0"), laneIndex(Onboard));
    // A pin would be asked for from a zero timer: let it run.
    QCoreApplication::processEvents();
    QCOMPARE(m_undo->count(), 0);
    QCOMPARE(pinnedNode(*m_model, QStringLiteral("Filter0")), QString());
    PlanCardItem *card = m_view->scene()->card(QStringLiteral("Filter0"));
    QCOMPARE(m_view->scene()->laneAt(card->sceneBoundingRect().center()), laneIndex(Onboard));
}

// The command with no node frees a component: the system's own pin comes back on undo.
void TestPlanView::freeingUndoesToThePin()
{
    const QString logger = QStringLiteral("Logger0");
    QCOMPARE(pinnedNode(*m_model, logger), Base);
    m_undo->push(new PinComponentCommand(m_model.get(), logger, QString()));
    QCOMPARE(m_undo->undoText(), QStringLiteral("Free Logger0"));
    QCOMPARE(pinnedNode(*m_model, logger), QString());
    const Profile::RtsComponent *component = m_model->component(logger);
    QVERIFY(
        std::none_of(component->properties.cbegin(), component->properties.cend(),
                     [](const Profile::RtsProperty &p) { return p.name == Planner::Key::Pin; }));
    // Its other properties stay.
    QCOMPARE(Profile::rtsPropertyValue(component->properties, QStringLiteral("deploy.cpu_share")),
             QStringLiteral("0.25"));
    m_undo->undo();
    QCOMPARE(pinnedNode(*m_model, logger), Base);
    m_undo->redo();
    QCOMPARE(pinnedNode(*m_model, logger), QString());
}

void TestPlanView::cardMenuPinsHereAndFrees()
{
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    std::unique_ptr<QMenu> menu(m_view->scene()->cardMenu(QStringLiteral("Filter0")));
    QVERIFY(menu);
    auto *pinHere = menu->findChild<QAction *>(QStringLiteral("planPinHere"));
    auto *free = menu->findChild<QAction *>(QStringLiteral("planFree"));
    QVERIFY(pinHere && free);
    QVERIFY(pinHere->isEnabled());
    QVERIFY(!free->isEnabled());
    pinHere->trigger();
    QCOMPARE(pinnedNode(*m_model, QStringLiteral("Filter0")), Onboard);
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Onboard);
    menu.reset(m_view->scene()->cardMenu(QStringLiteral("Logger0")));
    free = menu->findChild<QAction *>(QStringLiteral("planFree"));
    QVERIFY(free->isEnabled());
    QVERIFY(!menu->findChild<QAction *>(QStringLiteral("planPinHere"))->isEnabled());
    free->trigger();
    QCOMPARE(pinnedNode(*m_model, QStringLiteral("Logger0")), QString());
    QVERIFY(!cardOf(*m_view, QStringLiteral("Logger0"))->pinned);
    QCOMPARE(m_undo->count(), 2);
    QVERIFY(!m_view->scene()->cardMenu(QStringLiteral("Nobody")));
}

void TestPlanView::replanMovesTheRest()
{
    QVERIFY2(planOn(QStringLiteral("twins.yaml")), qPrintable(describe(*m_view)));
    // Alike nodes: the lidar's chain goes where its pinned logger is, so nothing crosses.
    QCOMPARE(laneOf(*m_view, QStringLiteral("Lidar0")), Base);
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Base);
    drag(QStringLiteral("Lidar0"), laneIndex(Onboard));
    QTRY_COMPARE(pinnedNode(*m_model, QStringLiteral("Lidar0")), Onboard);
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Base);
    QSignalSpy planned(m_view.get(), &PlanView::planChanged);
    m_view->replan();
    QVERIFY(m_view->isBusy());
    QVERIFY(planned.wait(PlanTimeoutMs));
    QVERIFY2(m_view->plan().feasible, qPrintable(describe(*m_view)));
    QVERIFY(!m_view->isOutOfDate());
    // The 1 kHz scan connector pulls the filter after its pinned source.
    QCOMPARE(laneOf(*m_view, QStringLiteral("Lidar0")), Onboard);
    QCOMPARE(laneOf(*m_view, QStringLiteral("Filter0")), Onboard);
    QCOMPARE(m_view->plan().placement(QStringLiteral("Filter0"))->node, Onboard);
}

void TestPlanView::unmetRequirementShownInRed()
{
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    drag(QStringLiteral("Lidar0"), laneIndex(Base));
    QTRY_COMPARE(pinnedNode(*m_model, QStringLiteral("Lidar0")), Base);
    QSignalSpy planned(m_view.get(), &PlanView::planChanged);
    m_view->replan();
    QVERIFY(planned.wait(PlanTimeoutMs));
    QVERIFY(!m_view->plan().feasible);
    // Pinned where its lidar is not: the planner says why, and the view shows it in red.
    QVERIFY(m_view->unmetList()->count() >= 1);
    QListWidgetItem *first = m_view->unmetList()->item(0);
    QVERIFY2(first->text().startsWith(QLatin1String("Lidar0: ")), qPrintable(first->text()));
    QCOMPARE(first->foreground().color(), QColor(200, 30, 30));
    const PlanCard *card = cardOf(*m_view, QStringLiteral("Lidar0"));
    QVERIFY(card);
    QVERIFY(!card->unmet.isEmpty());
    QVERIFY(cardOf(*m_view, QStringLiteral("Viewer0"))->unmet.isEmpty());
    QVERIFY2(m_view->statusText().contains(QLatin1String("No plan")),
             qPrintable(m_view->statusText()));
}

void TestPlanView::pinIsKeptBySavingTheSystem()
{
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    drag(QStringLiteral("Filter0"), laneIndex(Base));
    QTRY_COMPARE(pinnedNode(*m_model, QStringLiteral("Filter0")), Base);
    for (const Profile::FileFormat format : {Profile::FileFormat::Xml, Profile::FileFormat::Yaml}) {
        const QByteArray saved = Profile::serializeRtsProfile(m_model->profile(), format);
        Profile::Diagnostics diagnostics;
        const auto loaded = Profile::loadProfileData(saved, QStringLiteral("saved"), &diagnostics);
        QVERIFY(loaded && loaded->rts);
        SystemModel reloaded(*loaded->rts);
        QCOMPARE(pinnedNode(reloaded, QStringLiteral("Filter0")), Base);
        QCOMPARE(pinnedNode(reloaded, QStringLiteral("Lidar0")), QString());
    }
}

void TestPlanView::dryRunListsWhatWouldHappen()
{
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    m_view->dryRun();
    QListWidget *list = m_view->dryRunList();
    QCOMPARE(list->count(), m_model->componentIds().size() + m_view->plan().installs.size());
    QStringList lines;
    for (int i = 0; i < list->count(); ++i)
        lines << list->item(i)->text();
    QVERIFY2(
        lines.contains(
            QStringLiteral("Create Lidar0 (ConsoleIn) on %1 in a process of its own").arg(Onboard)),
        qPrintable(lines.join(QLatin1Char('\n'))));
    QVERIFY2(lines.contains(
                 QStringLiteral("Create Ctrl0 (Controller) on %1 in process Loop0").arg(Onboard)),
             qPrintable(lines.join(QLatin1Char('\n'))));
}

// Probes of a type no node loads: with the repository, it is installed on the node of this
// machine's architecture, and the lanes and the dry run say so.
void TestPlanView::installsFromRepositoryShownInLanes()
{
    const auto probes = load(QStringLiteral("probe.xml"));
    QVERIFY(probes && probes->rts);
    m_model->setProfile(*probes->rts);
    QTemporaryDir dir;
    QString arch;
    QString error;
    const QString repo = TestSupport::makeNativeRepository(dir.path(), &arch, &error);
    QVERIFY2(!repo.isEmpty(), qPrintable(error));
    const QString facts = dir.filePath(QStringLiteral("facts.yaml"));
    QFile file(facts);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QStringLiteral("- {name: other, os.name: Linux, os.arch: riscv64, "
                              "supported_languages: C++}\n"
                              "- {name: native, os.name: Linux, os.arch: %1, "
                              "supported_languages: C++}\n")
                   .arg(arch)
                   .toUtf8());
    file.close();
    QSignalSpy planned(m_view.get(), &PlanView::planChanged);
    QVERIFY(m_view->openFactsFile(facts));
    QVERIFY(planned.wait(PlanTimeoutMs));
    QVERIFY(!m_view->plan().feasible);
    m_view->openRepository(repo);
    QTRY_COMPARE_WITH_TIMEOUT(planned.size(), 2, PlanTimeoutMs);
    QVERIFY2(m_view->plan().feasible, qPrintable(describe(*m_view)));
    const QString package = QStringLiteral("rtc-rtstudiotests-packaging-native");
    const PlanLane &native = m_view->scene()->lanes().at(laneIndex(QStringLiteral("native")));
    QCOMPARE(native.installs, QStringList {package + QStringLiteral(" 2.0.0")});
    QCOMPARE(native.cards.size(), qsizetype(2));
    QCOMPARE(native.cards.first().installPackage, package);
    QVERIFY(m_view->scene()->lanes().at(laneIndex(QStringLiteral("other"))).installs.isEmpty());
    m_view->dryRun();
    QCOMPARE(m_view->dryRunList()->item(0)->text(),
             QStringLiteral("Install %1 2.0.0 on native").arg(package));
}

void TestPlanView::deployWaitsForTheTransaction()
{
    QAction *deploy = m_view->deployAction();
    QVERIFY(!deploy->isEnabled());
    QVERIFY(!deploy->toolTip().isEmpty());
    QVERIFY2(planOn(QStringLiteral("robot-nodes.yaml")), qPrintable(describe(*m_view)));
    QVERIFY(!deploy->isEnabled());
    QSignalSpy requested(m_view.get(), &PlanView::deployRequested);
    m_view->setDeployAvailable(true);
    QVERIFY(deploy->isEnabled());
    deploy->trigger();
    QCOMPARE(requested.size(), 1);
    QCOMPARE(requested.first().first().value<Planner::Plan>().placements.size(),
             m_view->plan().placements.size());
    // A system changed since the plan is not deployed as planned.
    m_undo->push(new PinComponentCommand(m_model.get(), QStringLiteral("Filter0"), Base));
    QVERIFY(!deploy->isEnabled());
}

void TestPlanView::cancelDropsTheResult()
{
    QVERIFY(m_view->openFactsFile(dataFile(QStringLiteral("robot-nodes.yaml"))));
    QVERIFY(m_view->isBusy());
    QSignalSpy planned(m_view.get(), &PlanView::planChanged);
    m_view->cancel();
    QVERIFY(!m_view->isBusy());
    QVERIFY2(m_view->statusText().contains(QLatin1String("Cancelled")),
             qPrintable(m_view->statusText()));
    // The worker still ends; its plan is not shown.
    QTRY_COMPARE_WITH_TIMEOUT(m_view->runningWorkers(), 0, PlanTimeoutMs);
    QCOMPARE(planned.size(), 0);
    QVERIFY(m_view->plan().placements.isEmpty());
}

QTEST_MAIN(TestPlanView)
#include "tst_planview.moc"

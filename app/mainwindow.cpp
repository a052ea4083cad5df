// SPDX-License-Identifier: MIT
#include "mainwindow.h"

#include "componenteditor.h"
#include "dialogprompts.h"
#include "document.h"
#include "documentcontroller.h"
#include "editorfactory.h"
#include "onlinedocks.h"
#include "openingprogress.h"
#include "problemspanel.h"
#include "recentfiles.h"
#include "rtsdocument.h"
#include "restoredialog.h"
#include "rtseditor.h"
#include "rtstudioresources.h"
#include "systemcanvas.h"
#include "uilanguage.h"
#include "onlinedocument.h"
#include "userguide.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QScreen>
#include <QStackedWidget>
#include <QStyle>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QUndoGroup>
#include <QUndoStack>

namespace Studio {

namespace {

const QString GeometryKey = QStringLiteral("mainWindow/geometry");
const QString StateKey = QStringLiteral("mainWindow/state");
const QString PerspectiveKey = QStringLiteral("mainWindow/perspective");

QIcon icon(const QString &name)
{
    return QIcon(Resources::iconPath(name));
}

} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_prompts(std::make_unique<DialogPrompts>(this))
    , m_controller(new DocumentController(m_prompts.get(), this))
    , m_undoGroup(new QUndoGroup(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    setWindowIcon(QIcon(Resources::applicationIconPath()));
    setAcceptDrops(true);
    createPerspectives();
    createProblemsDock();
    m_online = new OnlineDocks(this, new QSettings(this));
    m_online->attach(
        m_controller, [this] { return activeDocument(); },
        [this] { return m_prompts->askOpenFileNames(m_controller->lastDirectory()).value(0); });
    connect(m_online, &OnlineDocks::statusMessage, this,
            [this](const QString &message) { statusBar()->showMessage(message, 5000); });
    createActions();
    createMenus();
    createToolBar();
    connectController();
    statusBar()->addPermanentWidget(new OpeningProgress(m_controller, this));
    readSettings();
    updateActiveDocument();
}

MainWindow::~MainWindow()
{
    // Documents go first, while the perspectives that show them still exist.
    delete m_controller;
}

void MainWindow::setPrompts(std::unique_ptr<UserPrompts> prompts)
{
    m_controller->setPrompts(prompts.get());
    m_prompts = std::move(prompts);
}

Perspective *MainWindow::perspective(Perspective::Id id) const
{
    return id == Perspective::Id::Builder ? m_builder : m_systemEditor;
}

Perspective *MainWindow::currentPerspective() const
{
    return static_cast<Perspective *>(m_perspectives->currentWidget());
}

void MainWindow::showPerspective(Perspective::Id id)
{
    Perspective *target = perspective(id);
    m_perspectives->setCurrentWidget(target);
    m_online->setPerspectiveActive(id == Perspective::Id::SystemEditor);
    const QString actionName = id == Perspective::Id::Builder
        ? QStringLiteral("actionPerspectiveBuilder")
        : QStringLiteral("actionPerspectiveSystemEditor");
    if (auto *action = findChild<QAction *>(actionName))
        action->setChecked(true);
    updateActiveDocument();
}

Document *MainWindow::activeDocument() const
{
    return currentPerspective() ? currentPerspective()->currentDocument() : nullptr;
}

bool MainWindow::openFiles(const QStringList &paths)
{
    return m_controller->openFiles(paths).size() == paths.size();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    writeSettings();
    if (m_controller->closeAll()) {
        m_online->quitting();
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    if (event->mimeData()->hasUrls())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    QStringList paths;
    for (const QUrl &url : event->mimeData()->urls()) {
        if (url.isLocalFile())
            paths << url.toLocalFile();
    }
    if (!paths.isEmpty()) {
        event->acceptProposedAction();
        openFiles(paths);
    }
}

QAction *MainWindow::addAction(const QString &objectName, const QString &text,
                               const QString &iconName, const QKeySequence &shortcut)
{
    auto *action = new QAction(text, this);
    action->setObjectName(objectName);
    if (!iconName.isEmpty())
        action->setIcon(icon(iconName));
    if (!shortcut.isEmpty())
        action->setShortcut(shortcut);
    return action;
}

void MainWindow::createActions()
{
    createFileActions();
    createEditActions();
    createPerspectiveActions();
    QAction *about
        = addAction(QStringLiteral("actionAbout"), tr("&About RT Studio"), QStringLiteral("about"));
    about->setMenuRole(QAction::AboutRole);
    connect(about, &QAction::triggered, this, [this] { m_prompts->showAbout(); });
    const auto guideAction = [this](const char *objectName, const QString &text, const QString &page) {
        QAction *action = addAction(QLatin1String(objectName), text, QString());
        connect(action, &QAction::triggered, this, [this, page] { showUserGuide(page); });
        return action;
    };
    guideAction("actionUserGuide", tr("&User Guide"), QStringLiteral("getting-started.md"));
    guideAction("actionTroubleshooting", tr("&Troubleshooting"), QStringLiteral("troubleshooting.md"));
    QAction *context = addAction(QStringLiteral("actionContextHelp"), tr("Help on This &View"), QString(),
                                 QKeySequence::HelpContents);
    connect(context, &QAction::triggered, this,
            [this] { showUserGuide(QStringLiteral("rtstudio.md"), contextHelpSection()); });
}

QString MainWindow::contextHelpSection() const
{
    const Perspective *perspective = currentPerspective();
    if (perspective && perspective->id() == Perspective::Id::Builder) {
        const auto *component
            = qobject_cast<const Builder::ComponentEditor *>(perspective->editor(perspective->currentDocument()));
        return component ? component->helpSection() : QStringLiteral("Builder");
    }
    // A view with a section of its own, when the focus is in it (or in one of its windows).
    static const std::pair<const char *, const char *> views[]
        = {{"SystemEditor::PortMonitor", "Port Monitor"}, {"SystemEditor::PlanView", "Plan view"},
           {"SystemEditor::NameServiceView", "Online"},   {"SystemEditor::ManagerView", "Online"},
           {"SystemEditor::ConfigurationView", "Online"}, {"SystemEditor::ExecutionContextView", "Online"}};
    for (const QWidget *widget = QApplication::focusWidget(); widget; widget = widget->parentWidget()) {
        for (const auto &[className, section] : views) {
            if (widget->inherits(className))
                return QLatin1String(section);
        }
    }
    return qobject_cast<const OnlineDocument *>(m_activeDocument) ? QStringLiteral("Online")
                                                                   : QStringLiteral("System Editor");
}

void MainWindow::showUserGuide(const QString &page, const QString &section)
{
    if (!m_userGuide)
        m_userGuide = new UserGuide(this);
    m_userGuide->show();
    m_userGuide->raise();
    const QString language = UiLanguage::resolve(UiLanguage::chosen());
    if (section.isEmpty())
        m_userGuide->showPage(page, language);
    else
        m_userGuide->showSection(page, section, language);
}

void MainWindow::createFileActions()
{
    QAction *newComponent = addAction(QStringLiteral("actionNewComponent"), tr("New &Component"),
                                      QStringLiteral("new-component"), QKeySequence::New);
    newComponent->setToolTip(tr("Create a new RT-Component profile in the Builder"));
    connect(newComponent, &QAction::triggered, m_controller, &DocumentController::newComponent);

    QAction *newSystem
        = addAction(QStringLiteral("actionNewSystem"), tr("New &System"),
                    QStringLiteral("new-system"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    newSystem->setToolTip(tr("Create a new RT System in the System Editor"));
    connect(newSystem, &QAction::triggered, m_controller, &DocumentController::newSystem);

    QAction *open = addAction(QStringLiteral("actionOpen"), tr("&Open…"), QStringLiteral("open"),
                              QKeySequence::Open);
    open->setToolTip(tr("Open an RTC or RTS profile (XML or YAML)"));
    connect(open, &QAction::triggered, m_controller, &DocumentController::openWithDialog);

    addDocumentAction(QStringLiteral("actionSave"), tr("&Save"), QStringLiteral("save"),
                      QKeySequence::Save, [this](Document *d) { return m_controller->save(d); });
    addDocumentAction(QStringLiteral("actionSaveAs"), tr("Save &As…"), QStringLiteral("save-as"),
                      QKeySequence::SaveAs, [this](Document *d) { return m_controller->saveAs(d); });
    addDocumentAction(QStringLiteral("actionClose"), tr("&Close"), QStringLiteral("close"),
                      QKeySequence::Close, [this](Document *d) { return m_controller->close(d); });
    addDocumentAction(QStringLiteral("actionExportDiagram"), tr("&Export Diagram…"), QString(),
                      {}, [this](Document *d) { return m_controller->exportDiagram(d); });

    QAction *quit = addAction(QStringLiteral("actionQuit"), tr("&Quit"), QStringLiteral("quit"),
                              QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);
    connect(quit, &QAction::triggered, this, &QWidget::close);
}

void MainWindow::addDocumentAction(const QString &objectName, const QString &text,
                                   const QString &iconName, const QKeySequence &shortcut,
                                   const std::function<bool(Document *)> &operation)
{
    QAction *action = addAction(objectName, text, iconName, shortcut);
    connect(action, &QAction::triggered, this, [this, operation] {
        if (Document *document = activeDocument())
            operation(document);
    });
}

void MainWindow::createEditActions()
{
    // The group's actions follow the active stack: enabled state and "Undo <what>" text.
    QAction *undo = m_undoGroup->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("actionUndo"));
    undo->setIcon(icon(QStringLiteral("undo")));
    undo->setShortcut(QKeySequence::Undo);
    QAction *redo = m_undoGroup->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("actionRedo"));
    redo->setIcon(icon(QStringLiteral("redo")));
    redo->setShortcut(QKeySequence::Redo);
}

void MainWindow::createPerspectiveActions()
{
    m_perspectiveActions = new QActionGroup(this);
    const std::pair<Perspective *, QString> perspectives[] = {
        {m_builder, QStringLiteral("actionPerspectiveBuilder")},
        {m_systemEditor, QStringLiteral("actionPerspectiveSystemEditor")},
    };
    for (const auto &[target, name] : perspectives) {
        const bool builder = target == m_builder;
        QAction *action = addAction(
            name, target->title(), builder ? QStringLiteral("component") : QStringLiteral("system"),
            QKeySequence(Qt::CTRL | (builder ? Qt::Key_1 : Qt::Key_2)));
        action->setCheckable(true);
        action->setToolTip(tr("Switch to the %1 perspective").arg(target->title()));
        m_perspectiveActions->addAction(action);
        const Perspective::Id id = target->id();
        connect(action, &QAction::triggered, this, [this, id] { showPerspective(id); });
    }
}

void MainWindow::createMenus()
{
    const auto action
        = [this](const char *name) { return findChild<QAction *>(QLatin1String(name)); };
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(action("actionNewComponent"));
    file->addAction(action("actionNewSystem"));
    file->addSeparator();
    file->addAction(action("actionOpen"));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("menuRecentFiles"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::fillRecentFilesMenu);
    file->addSeparator();
    file->addAction(action("actionSave"));
    file->addAction(action("actionSaveAs"));
    file->addAction(action("actionClose"));
    file->addSeparator();
    file->addAction(action("actionExportDiagram"));
    file->addSeparator();
    file->addAction(action("actionQuit"));

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->setObjectName(QStringLiteral("menuEdit"));
    edit->addAction(action("actionUndo"));
    edit->addAction(action("actionRedo"));
    // The open system's canvas edits (copy, paste, group as composite, …) follow undo/redo;
    // they stay the canvas's actions, so their enabled state follows its selection.
    connect(edit, &QMenu::aboutToShow, this, [this, edit, action] {
        edit->clear();
        edit->addAction(action("actionUndo"));
        edit->addAction(action("actionRedo"));
        if (const auto *editor
            = qobject_cast<RtsEditor *>(currentPerspective()->editor(activeDocument()))) {
            edit->addSeparator();
            edit->addActions(editor->canvas()->editActions());
        }
    });

    QMenu *view = menuBar()->addMenu(tr("&View"));
    view->addActions(m_perspectiveActions->actions());
    view->addSeparator();
    view->addAction(m_problemsDock->toggleViewAction());
    view->addActions(m_online->toggleActions());
    view->addSeparator();
    createLanguageMenu(view->addMenu(tr("&Language")));

    QMenu *online = menuBar()->addMenu(tr("&Online"));
    QAction *restore = online->addAction(tr("&Restore System on Live Managers…"));
    restore->setObjectName(QStringLiteral("actionRestoreSystem"));
    connect(restore, &QAction::triggered, this, [this] {
        if (const auto *system = qobject_cast<RtsDocument *>(activeDocument()))
            m_online->openRestore(system->profile());
        else
            statusBar()->showMessage(tr("Open a system to restore it."), 5000);
    });
    m_online->fillMenu(online);
    // The Plan view's Deploy opens the Restore dialog on the pinned system, installing from the
    // plan's repository.
    RtsEditor::setDeployHandler([this](const Profile::RtsProfile &system, const QString &repository) {
        SystemEditor::RestoreDialog *dialog = m_online->openRestore(system);
        dialog->setCreateMissing(true, QString());
        if (!repository.isEmpty())
            dialog->setInstallFrom(repository);
    });

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(action("actionContextHelp"));
    help->addAction(action("actionUserGuide"));
    help->addAction(action("actionTroubleshooting"));
    help->addSeparator();
    help->addAction(action("actionAbout"));
    fillRecentFilesMenu();
}

void MainWindow::createLanguageMenu(QMenu *menu)
{
    menu->setObjectName(QStringLiteral("menuLanguage"));
    auto *group = new QActionGroup(menu);
    // Each language is named in itself, so that it can be found whatever the GUI shows now.
    const QList<std::pair<QString, QString>> choices = {
        {QString(), tr("System Default")},
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("ja"), QStringLiteral("日本語")},
    };
    const QString current = UiLanguage::chosen();
    for (const auto &[language, label] : choices) {
        QAction *choice = menu->addAction(label);
        choice->setObjectName(QStringLiteral("actionLanguage_")
                              + (language.isEmpty() ? QStringLiteral("system") : language));
        choice->setCheckable(true);
        choice->setChecked(language == current);
        group->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, language = language] {
            UiLanguage::choose(language);
            statusBar()->showMessage(
                tr("RT Studio shows the chosen language when it starts again."), 10000);
        });
    }
}

void MainWindow::createToolBar()
{
    QToolBar *bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->setMovable(false);
    for (const char *name : {"actionNewComponent", "actionNewSystem", "actionOpen", "actionSave"})
        bar->addAction(findChild<QAction *>(QLatin1String(name)));
    bar->addSeparator();
    bar->addAction(findChild<QAction *>(QStringLiteral("actionUndo")));
    bar->addAction(findChild<QAction *>(QStringLiteral("actionRedo")));

    // The perspective switcher sits at the right end, as in Eclipse-based OpenRTP.
    auto *spacer = new QWidget(bar);
    spacer->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    bar->addWidget(spacer);
    bar->addSeparator();
    for (QAction *action : m_perspectiveActions->actions()) {
        bar->addAction(action);
        if (auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(action)))
            button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    }
}

void MainWindow::createPerspectives()
{
    m_builder = new Perspective(Perspective::Id::Builder, tr("Builder"));
    m_builder->setObjectName(QStringLiteral("perspectiveBuilder"));
    m_builder->setEmptyHint(tr("<p><b>Builder</b></p><p>Design an RT-Component: "
                               "File ▸ New Component, or open an RTC profile (RTC.xml or "
                               "YAML) with File ▸ Open.</p>"));
    m_systemEditor = new Perspective(Perspective::Id::SystemEditor, tr("System Editor"));
    m_systemEditor->setObjectName(QStringLiteral("perspectiveSystemEditor"));
    m_systemEditor->setEmptyHint(tr("<p><b>System Editor</b></p><p>Compose RT-Components into "
                                    "a system: File ▸ New System, or open an RTS profile with "
                                    "File ▸ Open.</p>"));
    m_perspectives = new QStackedWidget(this);
    m_perspectives->addWidget(m_builder);
    m_perspectives->addWidget(m_systemEditor);
    setCentralWidget(m_perspectives);

    for (Perspective *perspective : {m_builder, m_systemEditor}) {
        connect(perspective, &Perspective::currentDocumentChanged, this,
                &MainWindow::updateActiveDocument);
        connect(perspective, &Perspective::closeRequested, m_controller,
                [this](Document *d) { return m_controller->close(d); });
    }
}

void MainWindow::createProblemsDock()
{
    m_problems = new ProblemsPanel;
    m_problemsDock = new QDockWidget(tr("Problems"), this);
    m_problemsDock->setObjectName(QStringLiteral("problemsDock"));
    m_problemsDock->setWidget(m_problems);
    addDockWidget(Qt::BottomDockWidgetArea, m_problemsDock);
    m_problemsDock->hide();
    connect(m_problems, &ProblemsPanel::profileRequested, this,
            [this](const QString &path) { openFiles({path}); });
    connect(m_problems, &ProblemsPanel::countChanged, this, [this](int count) {
        m_problemsDock->setWindowTitle(count > 0 ? tr("Problems (%1)").arg(count) : tr("Problems"));
    });
}

void MainWindow::connectController()
{
    connect(m_controller, &DocumentController::documentAdded, this, &MainWindow::addDocument);
    connect(m_controller, &DocumentController::activationRequested, this,
            &MainWindow::activateDocument);
    connect(m_controller, &DocumentController::documentClosing, this, &MainWindow::removeDocument);
    connect(m_controller, &DocumentController::problemsReported, this, &MainWindow::showProblems);
    connect(m_controller, &DocumentController::statusMessage, this,
            [this](const QString &message) { statusBar()->showMessage(message, 5000); });
    connect(m_controller->recentFiles(), &RecentFiles::changed, this,
            &MainWindow::fillRecentFilesMenu);
}

void MainWindow::addDocument(Document *document)
{
    const Perspective::Id id = document->kind() == Profile::ProfileKind::Rts
        ? Perspective::Id::SystemEditor
        : Perspective::Id::Builder;
    m_undoGroup->addStack(document->undoStack());
    connect(document, &Document::modifiedChanged, this, [this, document] {
        if (document == m_activeDocument) {
            updateTitle();
            updateActions();
        }
    });
    // Saving an untitled document gives it a name without changing its modified state.
    connect(document, &Document::filePathChanged, this, [this, document] {
        if (document == m_activeDocument) {
            updateTitle();
            updateActions();
        }
    });
    connect(document, &Document::displayNameChanged, this, [this, document] {
        if (document == m_activeDocument)
            updateTitle();
    });
    QWidget *editor = createEditor(document);
    // The Builder's Generate reports into the Problems panel and the status bar, not a dialog.
    if (auto *component = qobject_cast<Builder::ComponentEditor *>(editor))
        connect(component, &Builder::ComponentEditor::generationReported, this,
                &MainWindow::showGenerateOutcome);
    perspective(id)->addDocument(document, editor);
    showPerspective(id);
}

void MainWindow::activateDocument(Document *document)
{
    for (Perspective *target : {m_builder, m_systemEditor}) {
        if (target->contains(document)) {
            target->setCurrentDocument(document);
            showPerspective(target->id());
        }
    }
}

void MainWindow::removeDocument(Document *document)
{
    disconnect(document, nullptr, this, nullptr);
    m_undoGroup->removeStack(document->undoStack());
    if (m_activeDocument == document)
        m_activeDocument = nullptr;
    m_builder->removeDocument(document);
    m_systemEditor->removeDocument(document);
    updateActiveDocument();
}

void MainWindow::updateActiveDocument()
{
    m_activeDocument = activeDocument();
    m_undoGroup->setActiveStack(m_activeDocument ? m_activeDocument->undoStack() : nullptr);
    updateTitle();
    updateActions();
}

void MainWindow::updateTitle()
{
    const QString application = tr("RT Studio");
    const QString perspectiveTitle
        = currentPerspective() ? currentPerspective()->title() : QString();
    if (!m_activeDocument) {
        setWindowTitle(QStringLiteral("%1 — %2").arg(perspectiveTitle, application));
        setWindowModified(false);
        return;
    }
    // "[*]" is where Qt shows the modified marker; it shows only while windowModified is set.
    setWindowTitle(QStringLiteral("%1[*] — %2 — %3")
                       .arg(m_activeDocument->displayName(), perspectiveTitle, application));
    setWindowModified(m_activeDocument->isModified());
}

void MainWindow::updateActions()
{
    Document *document = m_activeDocument;
    findChild<QAction *>(QStringLiteral("actionSave"))
        ->setEnabled(document && (document->isModified() || document->isUntitled()));
    findChild<QAction *>(QStringLiteral("actionSaveAs"))->setEnabled(document != nullptr);
    findChild<QAction *>(QStringLiteral("actionClose"))->setEnabled(document != nullptr);
    findChild<QAction *>(QStringLiteral("actionExportDiagram"))
        ->setEnabled(qobject_cast<RtsDocument *>(document) != nullptr);
}

void MainWindow::fillRecentFilesMenu()
{
    // Reading the list may prune it, which announces a change and refills the menu from within;
    // clearing only afterwards keeps the entries from appearing twice.
    const QStringList files = m_controller->recentFiles()->files();
    m_recentMenu->clear();
    for (int i = 0; i < files.size(); ++i) {
        const QString path = files.at(i);
        // Numbered accelerators 1–9 make the first entries quick to pick from the keyboard.
        const QString text = i < 9
            ? QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName())
            : QFileInfo(path).fileName();
        QAction *action = m_recentMenu->addAction(text);
        action->setToolTip(path);
        action->setStatusTip(path);
        connect(action, &QAction::triggered, this, [this, path] { openFiles({path}); });
    }
    if (!files.isEmpty()) {
        m_recentMenu->addSeparator();
        QAction *clear = m_recentMenu->addAction(tr("Clear List"));
        connect(clear, &QAction::triggered, m_controller->recentFiles(), &RecentFiles::clear);
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::showGenerateOutcome(const Builder::GenerateOutcome &outcome)
{
    m_problems->setGenerateOutcome(outcome);
    statusBar()->showMessage(outcome.summary, 10000);
    // Success lists the files quietly; only problems bring the panel up.
    if (outcome.needsAttention())
        m_problemsDock->show();
}

void MainWindow::showProblems(const QString &summary, const Profile::Diagnostics &diagnostics)
{
    m_problems->setDiagnostics(summary, diagnostics);
    m_problemsDock->show();
    statusBar()->showMessage(summary, 5000);
}

void MainWindow::readSettings()
{
    QSettings settings;
    if (!restoreGeometry(settings.value(GeometryKey).toByteArray())) {
        // First start: 1200 × 800, or nine tenths of a smaller screen, centred on it.
        const QRect available = screen()->availableGeometry();
        const QSize size = QSize(1200, 800).boundedTo(available.size() * 9 / 10);
        setGeometry(QStyle::alignedRect(Qt::LeftToRight, Qt::AlignCenter, size, available));
    }
    restoreState(settings.value(StateKey).toByteArray());
    const bool systemEditor
        = settings.value(PerspectiveKey).toString() == QLatin1String("SystemEditor");
    showPerspective(systemEditor ? Perspective::Id::SystemEditor : Perspective::Id::Builder);
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.setValue(GeometryKey, saveGeometry());
    settings.setValue(StateKey, saveState());
    settings.setValue(PerspectiveKey,
                      currentPerspective()->id() == Perspective::Id::SystemEditor
                          ? QStringLiteral("SystemEditor")
                          : QStringLiteral("Builder"));
}

} // namespace Studio

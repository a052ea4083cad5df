// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "generateoutcome.h"
#include "perspective.h"

#include <QMainWindow>

#include <functional>
#include <memory>

class QAction;
class QActionGroup;
class QDockWidget;
class QMenu;
class QStackedWidget;
class QUndoGroup;

namespace Studio {

class UserGuide;

class Document;
class DocumentController;
class OnlineDocks;
class ProblemsPanel;
class UserPrompts;

/**
 * The RT Studio main window: the Builder and System Editor perspectives (switched from the
 * toolbar, each with its own document tabs), the File/Edit/View/Help menus, a Problems panel,
 * and the window title showing the active document with its modified marker.
 *
 * Undo and Redo act on the active document's undo stack (through a QUndoGroup). Window geometry,
 * toolbar/dock state and the last perspective are kept in QSettings. Actions have object names
 * (`actionSave`, `actionUndo`, …) by which tests and scripts can find them.
 */
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    /// Replaces the dialogs (e.g. with scripted answers in tests).
    void setPrompts(std::unique_ptr<UserPrompts> prompts);

    DocumentController *documents() const { return m_controller; }
    QUndoGroup *undoGroup() const { return m_undoGroup; }
    ProblemsPanel *problemsPanel() const { return m_problems; }
    QDockWidget *problemsDock() const { return m_problemsDock; }
    /// The online System Editor views (Name Service, Configuration, Execution Contexts).
    OnlineDocks *onlineDocks() const { return m_online; }

    Perspective *perspective(Perspective::Id id) const;
    Perspective *currentPerspective() const;
    void showPerspective(Perspective::Id id);

    /// The document of the current tab of the current perspective, or null.
    Document *activeDocument() const;
    /// Opens files as `rtstudio FILE…` does; true when all of them opened.
    bool openFiles(const QStringList &paths);
    /// Help → User Guide: shows @p page of docs/ (in the GUI's language where translated), at
    /// its heading @p section when given.
    void showUserGuide(const QString &page, const QString &section = {});
    /// What F1 shows here: the section of docs/rtstudio.md about the view in front.
    QString contextHelpSection() const;
    /// The user guide window, once shown.
    UserGuide *userGuide() const { return m_userGuide; }

protected:
    void closeEvent(QCloseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    QAction *addAction(const QString &objectName, const QString &text, const QString &icon,
                       const QKeySequence &shortcut = {});
    void createActions();
    void createFileActions();
    void addDocumentAction(const QString &objectName, const QString &text, const QString &icon,
                           const QKeySequence &shortcut,
                           const std::function<bool(Document *)> &operation);
    void createEditActions();
    void createPerspectiveActions();
    void createMenus();
    void createLanguageMenu(QMenu *menu);
    void createToolBar();
    void createPerspectives();
    void createProblemsDock();
    void connectController();

    void addDocument(Document *document);
    void activateDocument(Document *document);
    void removeDocument(Document *document);
    void updateActiveDocument();
    void updateTitle();
    void updateActions();
    void fillRecentFilesMenu();
    void showProblems(const QString &summary, const Profile::Diagnostics &diagnostics);
    void showGenerateOutcome(const Builder::GenerateOutcome &outcome);

    void readSettings();
    void writeSettings() const;

    std::unique_ptr<UserPrompts> m_prompts;
    DocumentController *m_controller;
    QUndoGroup *m_undoGroup;
    QStackedWidget *m_perspectives = nullptr;
    Perspective *m_builder = nullptr;
    Perspective *m_systemEditor = nullptr;
    QActionGroup *m_perspectiveActions = nullptr;
    ProblemsPanel *m_problems = nullptr;
    QDockWidget *m_problemsDock = nullptr;
    OnlineDocks *m_online = nullptr;
    QMenu *m_recentMenu = nullptr;
    Document *m_activeDocument = nullptr;
    UserGuide *m_userGuide = nullptr;
};

} // namespace Studio

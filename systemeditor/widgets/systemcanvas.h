// SPDX-License-Identifier: MIT
#pragma once

#include "compositedialog.h"

#include <QWidget>

#include <functional>
#include <optional>

class QAction;
class QLineEdit;
class QUndoStack;

namespace SystemEditor {

class OverviewWidget;
class SystemModel;
class SystemScene;
class SystemView;

/**
 * The System Editor's canvas of one system, ready to embed: the view with its scene, the
 * overview shown over its corner when the diagram is large, a find bar (Ctrl+F), and the
 * canvas actions (delete, copy, paste, select all, rename, zoom, fit, turn, align, grid) with
 * their shortcuts and a context menu. Actions have object names (`actionDelete`, …).
 *
 * When first shown it fits the diagram into the view (never beyond 100 %) and keeps it fitted
 * while the window settles, until the user zooms, scrolls or clicks.
 *
 * It takes the model and the undo stack; the document owning them lives elsewhere.
 */
class SystemCanvas : public QWidget
{
    Q_OBJECT

public:
    /**
     * Asks how to group `members` into a composite (kind and exported ports); nothing when
     * cancelled. The default shows a CompositeDialog.
     */
    using CompositeEditor = std::function<std::optional<CompositeDialog::Choice>(
        const SystemModel &model, const QStringList &members)>;

    SystemCanvas(SystemModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);
    ~SystemCanvas() override;

    SystemScene *scene() const { return m_scene; }
    SystemView *view() const { return m_view; }
    OverviewWidget *overview() const { return m_overview; }
    QLineEdit *findEdit() const { return m_findEdit; }
    /// The action with this object name, or null.
    QAction *action(const QString &objectName) const;
    /// Opens the find bar.
    void showFind();
    void setCompositeEditor(CompositeEditor editor) { m_compositeEditor = std::move(editor); }
    /// Groups the selected components into a composite after asking kind and exported ports
    /// (`actionGroupComposite`).
    void groupSelection();
    /// The actions that edit the selection, for an application's Edit menu.
    QList<QAction *> editActions() const;
    /// Lays every component out with autoLayoutCommand() as one undo step (`actionAutoLayout`).
    void autoLayout();

signals:
    void statusMessage(const QString &message);

protected:
    void resizeEvent(QResizeEvent *event) override;
    void showEvent(QShowEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QAction *addCanvasAction(const QString &objectName, const QString &text,
                             const QKeySequence &shortcut = {});
    void createEditActions();
    void createViewActions();
    void createArrangeActions();
    void updateActions();
    void placeOverview();
    void fitFreshDiagram();
    void showContextMenu(const QPoint &pos);

    SystemScene *m_scene;
    SystemView *m_view;
    OverviewWidget *m_overview;
    QWidget *m_findBar;
    QLineEdit *m_findEdit;
    /// True from opening until the user zooms, scrolls or clicks: until then the whole diagram
    /// is kept fitted into the view as the window settles into its size.
    CompositeEditor m_compositeEditor;
    bool m_keepFitted = true;
    bool m_fitting = false;
};

} // namespace SystemEditor

// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

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
 * It takes the model and the undo stack; the document owning them lives elsewhere.
 */
class SystemCanvas : public QWidget
{
    Q_OBJECT

public:
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
    /// Lays every component out with autoLayoutCommand() as one undo step (`actionAutoLayout`).
    void autoLayout();

signals:
    void statusMessage(const QString &message);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    QAction *addCanvasAction(const QString &objectName, const QString &text,
                             const QKeySequence &shortcut = {});
    void createEditActions();
    void createViewActions();
    void createArrangeActions();
    void updateActions();
    void placeOverview();
    void showContextMenu(const QPoint &pos);

    SystemScene *m_scene;
    SystemView *m_view;
    OverviewWidget *m_overview;
    QWidget *m_findBar;
    QLineEdit *m_findEdit;
};

} // namespace SystemEditor

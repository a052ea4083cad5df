// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "diagnostic.h"

#include <QPointer>
#include <QWidget>

#include <optional>

class QLabel;
class QListWidget;
class QPlainTextEdit;
class QPushButton;
class QUndoStack;

namespace Builder {

/**
 * The Builder's "RTC.xml" page: the profile as XML, editable by experts.
 *
 * Apply reads the text again. Errors are listed with line and column (double-click jumps there)
 * and the component stays as it was. A readable text is not taken at once: the page lists what
 * it would change, and Confirm replaces the profile as one undo step (Cancel keeps the text for
 * more editing). While the text has not been edited it follows every change of the component.
 */
class RtcXmlPage : public QWidget
{
    Q_OBJECT

public:
    RtcXmlPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    QPlainTextEdit *editor() const { return m_text; }

    /// Reads the text; shows errors (returns false) or the pending changes (returns true).
    bool apply();
    /// Takes the pending profile (one undo step).
    void confirm();
    /// Drops the pending profile, keeping the text.
    void cancel();
    /// Shows the component's XML again, dropping edits.
    void revert();

    /// The problems listed, as `LINE:COL: error: message`.
    QStringList problems() const;
    /// The pending changes listed (empty when nothing is pending).
    QStringList pendingChanges() const;
    /// True while the text differs from the XML of the component.
    bool isEdited() const;

protected:
    void showEvent(QShowEvent *event) override;

private:
    void followModel();
    void showText();
    void showProblems(const Profile::Diagnostics &diagnostics);
    void jumpTo(int line, int column);

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    QPlainTextEdit *m_text;
    QListWidget *m_problems;
    QWidget *m_pendingBox;
    QLabel *m_pendingLabel;
    QLabel *m_status;
    QString m_shownText; ///< the component's XML as last shown
    bool m_stale = false;
    std::optional<Profile::RtcProfile> m_pending;
    QStringList m_pendingChanges;
};

} // namespace Builder

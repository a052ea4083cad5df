// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "generateoutcome.h"

#include <QWidget>

class QLabel;
class QTreeWidget;

namespace Builder {
class SourceViewer;
}

namespace Studio {

/**
 * Lists the diagnostics of the last file operation (a failed load or save, or the warnings of a
 * successful load) or of the last Generate: one row per diagnostic with severity, location (file
 * and line, or the element it is about) and message.
 *
 * Double-clicking a row that names a file opens it: profiles (RTC.xml, RTS files) through
 * profileRequested(); text files (generated sources, IDL, files a build complained about) in
 * the panel's read-only source viewer beside the list, at the row's line; anything else with
 * the desktop's application.
 */
class ProblemsPanel : public QWidget
{
    Q_OBJECT

public:
    explicit ProblemsPanel(QWidget *parent = nullptr);

    /// Replaces the list; `summary` says what they are about (e.g. "Could not open x.xml").
    void setDiagnostics(const QString &summary, const Profile::Diagnostics &diagnostics);
    /// Shows what a Generate ended with (its summary and rows).
    void setGenerateOutcome(const Builder::GenerateOutcome &outcome);
    void clear();
    /// Does what double-clicking row `row` does.
    void activate(int row);

    int count() const;
    QString summary() const;
    /// Row `row` as `FILE:LINE:COL: severity: message`.
    QString text(int row) const;
    /// The location column of row `row` (file name and line, or the element).
    QString location(int row) const;
    /// The viewer activated rows open their text files in; hidden until one does.
    Builder::SourceViewer *sourceViewer() const { return m_viewer; }

signals:
    void countChanged(int count);
    /// A row naming a profile file was activated: the application opens it.
    void profileRequested(const QString &path);
    /// A row was activated (after the panel did what it could with it).
    void diagnosticActivated(const Profile::Diagnostic &diagnostic);

private:
    QLabel *m_summary;
    QTreeWidget *m_list;
    Builder::SourceViewer *m_viewer;
    Profile::Diagnostics m_diagnostics;
};

} // namespace Studio

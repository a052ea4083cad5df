// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"

#include <QWidget>

class QLabel;
class QTreeWidget;

namespace Studio {

/**
 * Lists the diagnostics of the last file operation (a failed load or save, or the warnings of a
 * successful load): one row per diagnostic with severity, location and message.
 */
class ProblemsPanel : public QWidget
{
    Q_OBJECT

public:
    explicit ProblemsPanel(QWidget *parent = nullptr);

    /// Replaces the list; `summary` says what they are about (e.g. "Could not open x.xml").
    void setDiagnostics(const QString &summary, const Profile::Diagnostics &diagnostics);
    void clear();

    int count() const;
    QString summary() const;
    /// Row `row` as `FILE:LINE:COL: severity: message`.
    QString text(int row) const;

signals:
    void countChanged(int count);

private:
    QLabel *m_summary;
    QTreeWidget *m_list;
    Profile::Diagnostics m_diagnostics;
};

} // namespace Studio

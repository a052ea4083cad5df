// SPDX-License-Identifier: MIT
#pragma once

#include "generateprompts.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace Builder {

/**
 * Asks what to do with one generated file that exists and differs from the fresh one: keep it,
 * merge (refresh only the `<rtc-template>` regions, keep everything else) or overwrite, with a
 * unified diff of the existing file against the fresh one and "apply to all remaining files".
 * Merge and overwrite back the existing file up first.
 */
class RegenerationDialog : public QDialog
{
    Q_OBJECT

public:
    RegenerationDialog(const QString &relativePath, const QByteArray &existing,
                       const QByteArray &fresh, QWidget *parent = nullptr);

    /// The decision of the button pressed (Keep until one is), with the check box's state.
    FileChoice choice() const;

    QPlainTextEdit *diffView() const { return m_diff; }
    QPushButton *button(Codegen::FileDecision decision) const;
    QCheckBox *applyToAllBox() const { return m_applyToAll; }

private:
    QPushButton *addChoice(const QString &text, const QString &toolTip,
                           Codegen::FileDecision decision);
    void showDiff(const QString &diff);

    QPlainTextEdit *m_diff;
    QCheckBox *m_applyToAll;
    QList<QPair<Codegen::FileDecision, QPushButton *>> m_buttons;
    Codegen::FileDecision m_decision = Codegen::FileDecision::Keep;
};

} // namespace Builder

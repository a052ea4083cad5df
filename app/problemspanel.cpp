// SPDX-License-Identifier: MIT
#include "problemspanel.h"

#include "profileio.h"
#include "sourceviewer.h"

#include <QDesktopServices>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QStyle>
#include <QTreeWidget>
#include <QUrl>
#include <QVBoxLayout>

namespace Studio {

namespace {

QIcon severityIcon(const QStyle *style, Profile::Diagnostic::Severity severity)
{
    switch (severity) {
    case Profile::Diagnostic::Severity::Error:
        return style->standardIcon(QStyle::SP_MessageBoxCritical);
    case Profile::Diagnostic::Severity::Warning:
        return style->standardIcon(QStyle::SP_MessageBoxWarning);
    case Profile::Diagnostic::Severity::Info:
        break;
    }
    return style->standardIcon(QStyle::SP_MessageBoxInformation);
}

QString locationText(const Profile::Diagnostic &diagnostic)
{
    // Rules of the component being edited name the element instead of a file.
    if (diagnostic.file.isEmpty())
        return diagnostic.object;
    QString text = QFileInfo(diagnostic.file).fileName();
    if (diagnostic.line > 0)
        text += QStringLiteral(":%1").arg(diagnostic.line);
    if (diagnostic.line > 0 && diagnostic.column > 0)
        text += QStringLiteral(":%1").arg(diagnostic.column);
    return text;
}

} // namespace

ProblemsPanel::ProblemsPanel(QWidget *parent)
    : QWidget(parent)
    , m_summary(new QLabel(this))
    , m_list(new QTreeWidget(this))
    , m_viewer(new Builder::SourceViewer(this))
{
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setText(tr("No problems."));
    m_list->setColumnCount(2);
    m_list->setHeaderLabels({tr("Location"), tr("Message")});
    m_list->setRootIsDecorated(false);
    m_list->setAlternatingRowColors(true);
    m_list->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_list->header()->setStretchLastSection(true);

    m_list->setObjectName(QStringLiteral("problemsList"));
    connect(m_list, &QTreeWidget::itemActivated, this,
            [this](QTreeWidgetItem *item) { activate(m_list->indexOfTopLevelItem(item)); });

    m_viewer->setObjectName(QStringLiteral("problemsSourceViewer"));
    m_viewer->hide();
    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setChildrenCollapsible(false);
    splitter->addWidget(m_list);
    splitter->addWidget(m_viewer);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_summary);
    layout->addWidget(splitter);
}

void ProblemsPanel::setDiagnostics(const QString &summary, const Profile::Diagnostics &diagnostics)
{
    m_diagnostics = diagnostics;
    m_summary->setText(summary);
    m_list->clear();
    for (const Profile::Diagnostic &diagnostic : diagnostics) {
        auto *item = new QTreeWidgetItem(m_list);
        item->setIcon(0, severityIcon(style(), diagnostic.severity));
        item->setText(0, locationText(diagnostic));
        item->setToolTip(0, diagnostic.file);
        item->setText(1, diagnostic.message);
        item->setToolTip(1, diagnostic.toString());
    }
    emit countChanged(count());
}

void ProblemsPanel::setGenerateOutcome(const Builder::GenerateOutcome &outcome)
{
    setDiagnostics(outcome.summary, outcome.diagnostics);
}

void ProblemsPanel::activate(int row)
{
    if (row < 0 || row >= m_diagnostics.size())
        return;
    const Profile::Diagnostic diagnostic = m_diagnostics.at(row);
    const QFileInfo info(diagnostic.file);
    if (info.isFile()) {
        QFile file(diagnostic.file);
        // Reading the start of the file is enough to tell a profile (see detectProfileKind()).
        const bool profile = file.open(QIODevice::ReadOnly)
            && Profile::detectProfileKind(file.read(4096)) != Profile::ProfileKind::Unknown;
        if (profile)
            emit profileRequested(diagnostic.file);
        else if (m_viewer->openFile(diagnostic.file, diagnostic.line, diagnostic.column))
            m_viewer->show();
        else
            QDesktopServices::openUrl(QUrl::fromLocalFile(info.absoluteFilePath()));
    }
    emit diagnosticActivated(diagnostic);
}

QString ProblemsPanel::location(int row) const
{
    const QTreeWidgetItem *item = m_list->topLevelItem(row);
    return item ? item->text(0) : QString();
}

void ProblemsPanel::clear()
{
    setDiagnostics(tr("No problems."), {});
}

int ProblemsPanel::count() const
{
    return int(m_diagnostics.size());
}

QString ProblemsPanel::summary() const
{
    return m_summary->text();
}

QString ProblemsPanel::text(int row) const
{
    return m_diagnostics.value(row).toString();
}

} // namespace Studio

// SPDX-License-Identifier: MIT
#include "componenteditor.h"

#include "activitypage.h"
#include "basicpage.h"
#include "buildoutputpanel.h"
#include "componentpreview.h"
#include "componentrules.h"
#include "configurationpage.h"
#include "dataportspage.h"
#include "documentationpage.h"
#include "languagepage.h"
#include "rtcxmlpage.h"
#include "serviceportspage.h"
#include "typecatalog.h"

#include <QCoreApplication>
#include <QMetaMethod>
#include <QSplitter>
#include <QTabWidget>
#include <QToolBar>
#include <QVBoxLayout>

#include <iterator>

namespace Builder {

ComponentEditor::ComponentEditor(ComponentModel *model, QUndoStack *undoStack, TypeCatalog *types,
                                 QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_types(types ? types : sharedTypeCatalog())
    , m_pages(new QTabWidget(this))
    , m_basicPage(new BasicPage(model, undoStack))
    , m_preview(new ComponentPreview(model, this))
    , m_toolBar(new QToolBar(tr("Builder"), this))
    , m_buildOutput(new BuildOutputPanel(this))
{
    m_pages->setTabPosition(QTabWidget::South);
    m_pages->setDocumentMode(true);
    addPages();

    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(m_pages);
    splitter->addWidget(m_preview);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({900, qMax(380, m_preview->sizeHint().width())});
    auto *outputSplitter = new QSplitter(Qt::Vertical, this);
    outputSplitter->addWidget(splitter);
    outputSplitter->addWidget(m_buildOutput);
    outputSplitter->setStretchFactor(0, 3);
    outputSplitter->setStretchFactor(1, 1);
    outputSplitter->setChildrenCollapsible(false);
    m_buildOutput->hide();
    m_toolBar->setObjectName(QStringLiteral("builderToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_toolBar->hide();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_toolBar);
    layout->addWidget(outputSplitter, 1);

    connect(m_basicPage, &BasicPage::generateRequested, this, &ComponentEditor::requestGenerate);
    connect(m_basicPage, &BasicPage::codeRestoreRequested, this,
            &ComponentEditor::codeRestoreRequested);
    connect(m_basicPage, &BasicPage::clearBackupsRequested, this,
            &ComponentEditor::clearBackupsRequested);
}

namespace {

/// The pages' titles in tab order, untranslated: the user guide's sections are named after them.
constexpr const char *PageTitles[] = {QT_TRANSLATE_NOOP("Builder::ComponentEditor", "Basic"),
                                      QT_TRANSLATE_NOOP("Builder::ComponentEditor", "Activity"),
                                      QT_TRANSLATE_NOOP("Builder::ComponentEditor", "Data Ports"),
                                      QT_TRANSLATE_NOOP("Builder::ComponentEditor", "Service Ports"),
                                      QT_TRANSLATE_NOOP("Builder::ComponentEditor", "Configuration"),
                                      QT_TRANSLATE_NOOP("Builder::ComponentEditor", "Documentation"),
                                      QT_TRANSLATE_NOOP("Builder::ComponentEditor", "Language/Environment"),
                                      QT_TRANSLATE_NOOP("Builder::ComponentEditor", "RTC.xml")};

} // namespace

void ComponentEditor::addPages()
{
    QWidget *pages[] = {m_basicPage,
                        new ActivityPage(m_model, m_undoStack),
                        new DataPortsPage(m_model, m_undoStack, m_types),
                        new ServicePortsPage(m_model, m_undoStack, m_types),
                        new ConfigurationPage(m_model, m_undoStack),
                        new DocumentationPage(m_model, m_undoStack),
                        new LanguagePage(m_model, m_undoStack),
                        new RtcXmlPage(m_model, m_undoStack)};
    static_assert(std::size(pages) == std::size(PageTitles));
    for (size_t i = 0; i < std::size(pages); ++i)
        m_pages->addTab(pages[i], tr(PageTitles[i]));
}

QString ComponentEditor::helpSection() const
{
    const int current = m_pages->currentIndex();
    return current >= 0 && size_t(current) < std::size(PageTitles)
               ? QLatin1String(PageTitles[current]) + QLatin1String(" page")
               : QStringLiteral("Builder");
}

QWidget *ComponentEditor::page(const QString &title) const
{
    for (int i = 0; i < m_pages->count(); ++i) {
        if (m_pages->tabText(i) == title)
            return m_pages->widget(i);
    }
    return nullptr;
}

TypeCatalog *ComponentEditor::sharedTypeCatalog()
{
    // One per application, parented to it so it goes away with it; IDL is parsed once.
    static QPointer<TypeCatalog> catalog;
    if (!catalog) {
        catalog = new TypeCatalog(QString(), QCoreApplication::instance());
        catalog->startReload();
    }
    return catalog;
}

void ComponentEditor::requestGenerate()
{
    if (!m_model)
        return;
    Profile::Diagnostics problems = generationProblems(m_model->profile());
    // The generator needs every interface's IDL; an empty list means no IDL could be read.
    m_types->waitForLoaded();
    const QStringList known = m_types->interfaceTypes();
    for (const Profile::RtcServicePort &port : m_model->profile().servicePorts) {
        for (const Profile::RtcServiceInterface &interface : port.interfaces) {
            if (known.isEmpty() || interface.type.isEmpty() || known.contains(interface.type))
                continue;
            Profile::Diagnostic d = Profile::Diagnostic::error(
                QString(), 0, 0,
                tr("The interface type '%1' is not declared in any parsed IDL file.")
                    .arg(interface.type));
            d.object = tr("interface %1 of %2").arg(interface.name, port.name);
            problems.append(d);
        }
    }
    m_basicPage->showGenerationProblems(problems);
    if (problems.isEmpty()) {
        emit generateRequested();
        return;
    }
    emit generateRefused(problems);
    emit generationReported(GenerateOutcome::refused(problems));
}

void ComponentEditor::reportGeneration(const GenerateOutcome &outcome)
{
    emit generationReported(outcome);
}

bool ComponentEditor::reportsGeneration() const
{
    return isSignalConnected(QMetaMethod::fromSignal(&ComponentEditor::generationReported));
}

} // namespace Builder

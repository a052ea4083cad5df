// SPDX-License-Identifier: MIT
#include "dataportspage.h"

#include "componentrules.h"
#include "idlsettingsdialog.h"
#include "itemform.h"
#include "itemtablemodel.h"
#include "listeditor.h"
#include "typecatalog.h"

#include <QLabel>
#include <QScrollArea>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

namespace Builder {

namespace {

using Profile::RtcDataPort;
using Profile::RtcDataPortDoc;

QList<ItemField> tableColumns(TypeCatalog *types)
{
    ItemField type = textField<RtcDataPort>(QStringLiteral("type"), DataPortsPage::tr("Data type"),
                                            &RtcDataPort::type);
    type.choices = [types] { return types->dataTypes(); };
    ItemField position = textField<RtcDataPort>(
        QStringLiteral("position"), DataPortsPage::tr("Position"), &RtcDataPort::position);
    position.choices = [] { return Profile::rtcPositions(); };
    position.editableChoices = false;
    return {
        textField<RtcDataPort>(QStringLiteral("name"), DataPortsPage::tr("Name"),
                               &RtcDataPort::name),
        type,
        optionalTextField<RtcDataPort>(QStringLiteral("variableName"),
                                       DataPortsPage::tr("Variable name"),
                                       &RtcDataPort::variableName),
        position,
    };
}

} // namespace

DataPortsPage::DataPortsPage(ComponentModel *model, QUndoStack *undoStack, TypeCatalog *types,
                             QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_types(types)
{
    m_composite = new QLabel(this);
    m_composite->setStyleSheet(QStringLiteral("color: #b3261e;"));
    m_composite->setWordWrap(true);
    m_inPorts = makeList(Profile::RtcPortType::DataIn, tr("InPorts"));
    m_outPorts = makeList(Profile::RtcPortType::DataOut, tr("OutPorts"));
    buildForm();

    auto *tables = new QWidget(this);
    auto *tablesLayout = new QVBoxLayout(tables);
    tablesLayout->setContentsMargins(0, 0, 0, 0);
    tablesLayout->addWidget(createTypeCatalogButtons(types, tables));
    tablesLayout->addWidget(m_composite);
    tablesLayout->addWidget(m_inPorts);
    tablesLayout->addWidget(m_outPorts);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setWidget(m_form);
    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(tables);
    splitter->addWidget(scroll);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(splitter);

    connect(m_inPorts, &ListEditor::currentItemChanged, this, &DataPortsPage::showPort);
    connect(m_outPorts, &ListEditor::currentItemChanged, this, &DataPortsPage::showPort);
    connect(types, &TypeCatalog::typesChanged, m_form, &ItemForm::reloadChoices);
    connect(model, &ComponentModel::changed, this, &DataPortsPage::refreshComposite);
    refreshComposite();
}

ListEditor *DataPortsPage::makeList(Profile::RtcPortType type, const QString &title)
{
    const auto filter
        = [type](const PartItem &item) { return std::get<RtcDataPort>(item).kind() == type; };
    auto *table
        = new ItemTableModel(m_model, m_undoStack, Part::DataPort, tableColumns(m_types), filter);
    const auto factory = [this, type]() -> PartItem {
        RtcDataPort port;
        port.portType = Profile::rtcPortTypeText(type);
        const bool in = type == Profile::RtcPortType::DataIn;
        port.name = uniqueName(in ? QStringLiteral("in") : QStringLiteral("out"),
                               portNames(m_model->profile()));
        port.type = QStringLiteral("RTC::TimedLong");
        port.position = in ? QStringLiteral("LEFT") : QStringLiteral("RIGHT");
        return port;
    };
    auto *list = new ListEditor(m_model, m_undoStack, table, title, factory, this);
    list->setObjectName(type == Profile::RtcPortType::DataIn ? QStringLiteral("inPorts")
                                                             : QStringLiteral("outPorts"));
    return list;
}

void DataPortsPage::buildForm()
{
    m_form = new ItemForm(m_model, m_undoStack, Part::DataPort);
    m_form->addSection(tr("Port"));
    for (const ItemField &field : tableColumns(m_types))
        m_form->addField(field);
    m_form->addField(optionalTextField<RtcDataPort>(QStringLiteral("idlFile"), tr("IDL file"),
                                                    &RtcDataPort::idlFile));
    m_form->addSection(tr("Documentation"));
    const auto doc = [this](const char *key, const QString &label,
                            std::optional<QString> RtcDataPortDoc::*member) {
        m_form->addField(docField<RtcDataPort, RtcDataPortDoc>(QLatin1String(key), label,
                                                               &RtcDataPort::doc, member));
    };
    doc("doc.description", tr("Description"), &RtcDataPortDoc::description);
    doc("doc.type", tr("Data type description"), &RtcDataPortDoc::type);
    doc("doc.number", tr("Number of data"), &RtcDataPortDoc::number);
    doc("doc.semantics", tr("Semantics"), &RtcDataPortDoc::semantics);
    doc("doc.unit", tr("Unit"), &RtcDataPortDoc::unit);
    doc("doc.occerrence", tr("Occurrence frequency"), &RtcDataPortDoc::occerrence);
    doc("doc.operation", tr("Operation frequency"), &RtcDataPortDoc::operation);
}

void DataPortsPage::showPort(int itemIndex)
{
    // One form for both tables: selecting in one clears the other.
    auto *source = static_cast<ListEditor *>(sender());
    ListEditor *other = source == m_inPorts ? m_outPorts : m_inPorts;
    if (itemIndex >= 0) {
        const QSignalBlocker blocker(other);
        other->view()->setCurrentIndex({});
        m_form->setCurrentIndex(itemIndex);
    } else if (other->currentItem() < 0) {
        m_form->setCurrentIndex(-1);
    }
}

void DataPortsPage::refreshComposite()
{
    const QString problem = m_model ? compositePortsProblem(m_model->profile()) : QString();
    m_composite->setText(problem);
    m_composite->setVisible(!problem.isEmpty());
}

} // namespace Builder

// SPDX-License-Identifier: MIT
#include "dataportspage.h"

#include "componentrules.h"
#include "eventtablemodel.h"
#include "idlsettingsdialog.h"
#include "itemform.h"
#include "itemtablemodel.h"
#include "listeditor.h"
#include "typecatalog.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
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
    m_eventPorts = makeList(Profile::RtcPortType::Event, tr("EventPorts (FSM)"));
    buildForm();

    auto *tables = new QWidget(this);
    auto *tablesLayout = new QVBoxLayout(tables);
    tablesLayout->setContentsMargins(0, 0, 0, 0);
    tablesLayout->addWidget(createTypeCatalogButtons(types, tables));
    tablesLayout->addWidget(m_composite);
    tablesLayout->addWidget(m_inPorts);
    tablesLayout->addWidget(m_outPorts);
    tablesLayout->addWidget(m_eventPorts);
    tablesLayout->addWidget(buildEventsBox());
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
    connect(m_eventPorts, &ListEditor::currentItemChanged, this, &DataPortsPage::showPort);
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
        const bool out = type == Profile::RtcPortType::DataOut;
        const bool event = type == Profile::RtcPortType::Event;
        const QString base = event ? QStringLiteral("event")
            : out                  ? QStringLiteral("out")
                                   : QStringLiteral("in");
        port.name = uniqueName(base, portNames(m_model->profile()));
        // RTC Builder gives an EventPort the data type Any: events carry their own types.
        port.type = event ? QStringLiteral("Any") : QStringLiteral("RTC::TimedLong");
        port.position = out ? QStringLiteral("RIGHT") : QStringLiteral("LEFT");
        return port;
    };
    auto *list = new ListEditor(m_model, m_undoStack, table, title, factory, this);
    list->setObjectName(type == Profile::RtcPortType::DataIn        ? QStringLiteral("inPorts")
                            : type == Profile::RtcPortType::DataOut ? QStringLiteral("outPorts")
                                                                    : QStringLiteral("eventPorts"));
    return list;
}

QGroupBox *DataPortsPage::buildEventsBox()
{
    m_eventsBox = new QGroupBox(tr("Events of the selected EventPort"), this);
    m_eventsBox->setObjectName(QStringLiteral("eventsBox"));
    m_eventTable = new EventTableModel(m_model, m_undoStack, this);
    m_events = new QTableView(m_eventsBox);
    m_events->setModel(m_eventTable);
    m_events->horizontalHeader()->setStretchLastSection(true);
    m_events->verticalHeader()->hide();
    auto *add = new QPushButton(tr("Add Event"), m_eventsBox);
    add->setObjectName(QStringLiteral("addEvent"));
    auto *remove = new QPushButton(tr("Remove Event"), m_eventsBox);
    remove->setObjectName(QStringLiteral("removeEvent"));
    connect(add, &QPushButton::clicked, this, [this] {
        if (m_eventTable->addEvent())
            m_events->setCurrentIndex(m_eventTable->index(m_eventTable->rowCount() - 1, 0));
    });
    connect(remove, &QPushButton::clicked, this,
            [this] { m_eventTable->removeEvent(m_events->currentIndex().row()); });
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    auto *layout = new QVBoxLayout(m_eventsBox);
    layout->addWidget(m_events);
    layout->addLayout(buttons);
    m_eventsBox->setEnabled(false);
    return m_eventsBox;
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
    // One form for all tables: selecting in one clears the others.
    auto *source = static_cast<ListEditor *>(sender());
    bool othersEmpty = true;
    for (ListEditor *other : {m_inPorts, m_outPorts, m_eventPorts}) {
        if (other == source)
            continue;
        if (itemIndex >= 0) {
            const QSignalBlocker blocker(other);
            other->view()->setCurrentIndex({});
        }
        othersEmpty = othersEmpty && other->currentItem() < 0;
    }
    if (itemIndex >= 0)
        m_form->setCurrentIndex(itemIndex);
    else if (othersEmpty)
        m_form->setCurrentIndex(-1);
    const int eventPort = m_eventPorts->currentItem();
    m_eventTable->setPortIndex(eventPort);
    m_eventsBox->setEnabled(eventPort >= 0);
}

void DataPortsPage::refreshComposite()
{
    const QString problem = m_model ? compositePortsProblem(m_model->profile()) : QString();
    m_composite->setText(problem);
    m_composite->setVisible(!problem.isEmpty());
}

} // namespace Builder

// SPDX-License-Identifier: MIT
#include "serviceportspage.h"

#include "componentrules.h"
#include "idlsettingsdialog.h"
#include "itemcommands.h"
#include "itemform.h"
#include "listeditor.h"
#include "serviceporttreemodel.h"
#include "typecatalog.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QStackedWidget>
#include <QTreeView>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

using Profile::RtcServiceInterface;
using Profile::RtcServiceInterfaceDoc;
using Profile::RtcServicePort;

/// A text of the interface the form currently edits (`*current` in the port's list).
ItemField interfaceField(const QString &key, const QString &label, const int *current,
                         std::function<QString &(RtcServiceInterface &)> access)
{
    ItemField field;
    field.key = key;
    field.label = label;
    field.get = [current, access](const PartItem &item) {
        auto port = std::get<RtcServicePort>(item);
        if (*current < 0 || *current >= port.interfaces.size())
            return QString();
        return access(port.interfaces[*current]);
    };
    field.set = [current, access](PartItem &item, const QString &text) {
        auto &port = std::get<RtcServicePort>(item);
        if (*current >= 0 && *current < port.interfaces.size())
            access(port.interfaces[*current]) = text;
    };
    return field;
}

/// Access to an optional member (of the interface, or of its documentation `holder`); writing
/// creates what is missing.
template<typename T>
std::function<QString &(RtcServiceInterface &)>
optionalAccess(std::optional<QString> T::*member,
               std::optional<T> RtcServiceInterface::*holder = nullptr)
{
    return [member, holder](RtcServiceInterface &i) -> QString & {
        if constexpr (std::is_same_v<T, RtcServiceInterface>) {
            auto &value = i.*member;
            if (!value)
                value = QString();
            return *value;
        } else {
            auto &doc = i.*holder;
            if (!doc)
                doc = T();
            auto &value = (*doc).*member;
            if (!value)
                value = QString();
            return *value;
        }
    };
}

} // namespace

ServicePortsPage::ServicePortsPage(ComponentModel *model, QUndoStack *undoStack, TypeCatalog *types,
                                   QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_types(types)
    , m_tree(new ServicePortTreeModel(model, this))
    , m_view(new QTreeView(this))
    , m_forms(new QStackedWidget(this))
{
    m_view->setModel(m_tree);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->header()->setStretchLastSection(true);
    m_view->setColumnWidth(0, 200);
    m_view->expandAll();

    auto *addPort = new QPushButton(tr("Add Port"), this);
    m_addInterface = new QPushButton(tr("Add Interface"), this);
    m_remove = new QPushButton(tr("Remove"), this);
    connect(addPort, &QPushButton::clicked, this, &ServicePortsPage::addPort);
    connect(m_addInterface, &QPushButton::clicked, this, &ServicePortsPage::addInterface);
    connect(m_remove, &QPushButton::clicked, this, &ServicePortsPage::removeSelected);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(addPort);
    buttons->addWidget(m_addInterface);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    auto *left = new QVBoxLayout;
    left->addWidget(createTypeCatalogButtons(types, this));
    left->addWidget(new QLabel(tr("<b>Service ports</b>"), this));
    left->addWidget(m_view, 1);
    left->addLayout(buttons);

    buildPortForm();
    buildInterfaceForm();
    auto *empty = new QLabel(tr("Select a service port or an interface."), this);
    empty->setAlignment(Qt::AlignCenter);
    m_forms->addWidget(empty);
    for (ItemForm *form : {m_portForm, m_interfaceForm}) {
        auto *scroll = new QScrollArea(this);
        scroll->setWidgetResizable(true);
        scroll->setWidget(form);
        m_forms->addWidget(scroll);
    }
    auto *layout = new QHBoxLayout(this);
    layout->addLayout(left, 3);
    layout->addWidget(m_forms, 2);

    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &ServicePortsPage::showSelection);
    connect(m_tree, &QAbstractItemModel::modelReset, this, [this] {
        m_view->expandAll();
        showSelection();
    });
    connect(types, &TypeCatalog::typesChanged, this, [this] { m_interfaceForm->reloadChoices(); });
    showSelection();
}

void ServicePortsPage::buildPortForm()
{
    m_portForm = new ItemForm(m_model, m_undoStack, Part::ServicePort);
    m_portForm->addSection(tr("Service port"));
    m_portForm->addField(
        textField<RtcServicePort>(QStringLiteral("name"), tr("Port name"), &RtcServicePort::name));
    ItemField position = textField<RtcServicePort>(QStringLiteral("position"), tr("Position"),
                                                   &RtcServicePort::position);
    position.choices = [] { return Profile::rtcPositions(); };
    position.editableChoices = false;
    m_portForm->addField(position);
    m_portForm->addSection(tr("Documentation"));
    m_portForm->addField(docField<RtcServicePort, Profile::RtcServicePortDoc>(
        QStringLiteral("doc.description"), tr("Description"), &RtcServicePort::doc,
        &Profile::RtcServicePortDoc::description));
    m_portForm->addField(docField<RtcServicePort, Profile::RtcServicePortDoc>(
        QStringLiteral("doc.ifdescription"), tr("Interface description"), &RtcServicePort::doc,
        &Profile::RtcServicePortDoc::ifdescription));
}

void ServicePortsPage::buildInterfaceForm()
{
    m_interfaceForm = new ItemForm(m_model, m_undoStack, Part::ServicePort);
    m_interfaceForm->setProblems([this](const Profile::RtcProfile &profile, int port) {
        return m_interface >= 0 && m_interface < profile.servicePorts.at(port).interfaces.size()
            ? interfaceProblems(profile, port, m_interface)
            : FieldProblems();
    });
    const int *current = &m_interface;
    const auto plain = [](QString RtcServiceInterface::*member) {
        return [member](RtcServiceInterface &i) -> QString & { return i.*member; };
    };
    m_interfaceForm->addSection(tr("Interface"));
    m_interfaceForm->addField(interfaceField(QStringLiteral("name"), tr("Interface name"), current,
                                             plain(&RtcServiceInterface::name)));
    ItemField direction = interfaceField(QStringLiteral("direction"), tr("Direction"), current,
                                         plain(&RtcServiceInterface::direction));
    direction.choices = [] { return Profile::rtcDirections(); };
    direction.editableChoices = false;
    m_interfaceForm->addField(direction);
    m_interfaceForm->addField(interfaceField(QStringLiteral("instanceName"), tr("Instance name"),
                                             current,
                                             optionalAccess(&RtcServiceInterface::instanceName)));
    m_interfaceForm->addField(interfaceField(QStringLiteral("variableName"), tr("Variable name"),
                                             current,
                                             optionalAccess(&RtcServiceInterface::variableName)));
    ItemField type = interfaceField(QStringLiteral("type"), tr("Interface type"), current,
                                    plain(&RtcServiceInterface::type));
    type.choices = [this] { return m_types->interfaceTypes(); };
    m_interfaceForm->addField(type);
    m_interfaceForm->addField(interfaceField(QStringLiteral("idlFile"), tr("IDL file"), current,
                                             optionalAccess(&RtcServiceInterface::idlFile)));
    m_interfaceForm->addSection(tr("Documentation"));
    const auto doc = [&](const char *key, const QString &label,
                         std::optional<QString> RtcServiceInterfaceDoc::*member) {
        m_interfaceForm->addField(interfaceField(
            QLatin1String(key), label, current,
            optionalAccess<RtcServiceInterfaceDoc>(member, &RtcServiceInterface::doc)));
    };
    doc("doc.description", tr("Description"), &RtcServiceInterfaceDoc::description);
    doc("doc.argument", tr("Argument"), &RtcServiceInterfaceDoc::docArgument);
    doc("doc.return", tr("Return value"), &RtcServiceInterfaceDoc::docReturn);
    doc("doc.exception", tr("Exception"), &RtcServiceInterfaceDoc::docException);
    doc("doc.preCondition", tr("Precondition"), &RtcServiceInterfaceDoc::docPreCondition);
    doc("doc.postCondition", tr("Postcondition"), &RtcServiceInterfaceDoc::docPostCondition);
}

void ServicePortsPage::showSelection()
{
    const QModelIndex current = m_view->currentIndex();
    const int port = ServicePortTreeModel::portOf(current);
    const int interface = ServicePortTreeModel::interfaceOf(current);
    m_selectedPort = port;
    m_interface = interface;
    m_addInterface->setEnabled(port >= 0);
    m_remove->setEnabled(port >= 0);
    if (port < 0) {
        m_portForm->setCurrentIndex(-1);
        m_interfaceForm->setCurrentIndex(-1);
        m_forms->setCurrentIndex(0);
        return;
    }
    m_interfaceForm->setMergePrefix(QStringLiteral("interface%1.").arg(interface));
    if (interface < 0) {
        m_portForm->setCurrentIndex(port);
        m_interfaceForm->setCurrentIndex(-1);
        m_forms->setCurrentIndex(1);
    } else {
        m_portForm->setCurrentIndex(-1);
        m_interfaceForm->setCurrentIndex(port);
        m_forms->setCurrentIndex(2);
    }
}

void ServicePortsPage::select(int port, int interface)
{
    m_view->setCurrentIndex(m_tree->indexFor(port, interface));
    showSelection();
}

void ServicePortsPage::addPort()
{
    RtcServicePort port;
    port.name = uniqueName(QStringLiteral("port"), portNames(m_model->profile()));
    port.position = QStringLiteral("LEFT");
    const int at = m_model->itemCount(Part::ServicePort);
    m_undoStack->push(new InsertItemCommand(m_model, Part::ServicePort, at, port));
    select(at);
}

void ServicePortsPage::addInterface()
{
    const int port = m_selectedPort;
    if (port < 0)
        return;
    QStringList used;
    for (const RtcServiceInterface &i : m_model->profile().servicePorts.at(port).interfaces)
        used << i.name;
    RtcServiceInterface interface;
    interface.name = uniqueName(QStringLiteral("interface"), used);
    interface.direction = QStringLiteral("Provided");
    interface.type = m_types->interfaceTypes().value(0);
    const int at = int(used.size());
    m_undoStack->push(makeAddInterfaceCommand(m_model, port, interface));
    select(port, at);
}

void ServicePortsPage::removeSelected()
{
    const int port = m_selectedPort;
    const int interface = m_interface;
    if (port < 0)
        return;
    if (interface < 0)
        m_undoStack->push(new RemoveItemCommand(m_model, Part::ServicePort, port));
    else
        m_undoStack->push(makeRemoveInterfaceCommand(m_model, port, interface));
}

} // namespace Builder

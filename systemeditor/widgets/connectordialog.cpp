// SPDX-License-Identifier: MIT
#include "connectordialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

/// An editable combo box: offline there is no port to ask, so the user may type other values.
QComboBox *choiceBox(const QString &objectName, const QStringList &items, bool allowEmpty = false)
{
    auto *box = new QComboBox;
    box->setObjectName(objectName);
    box->setEditable(true);
    if (allowEmpty)
        box->addItem(QString());
    box->addItems(items);
    return box;
}

QLineEdit *lineEdit(const QString &objectName)
{
    auto *edit = new QLineEdit;
    edit->setObjectName(objectName);
    return edit;
}

void setChoice(QComboBox *box, const QString &text)
{
    box->setCurrentText(text);
}

} // namespace

ConnectorDialog::ConnectorDialog(const ConnectorSettings &settings, QWidget *parent)
    : ConnectorDialog(settings, Choices(), parent)
{ }

ConnectorDialog::ConnectorDialog(const ConnectorSettings &settings, const Choices &choices,
                                 QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Data Connector"));
    buildForm(choices);
    setSettings(settings);
}

void ConnectorDialog::buildForm(const Choices &choices)
{
    auto *general = new QFormLayout;
    m_name = lineEdit(QStringLiteral("name"));
    m_name->setMaxLength(ConnectorSettings::MaxNameLength + 1);
    m_dataType = lineEdit(QStringLiteral("dataType"));
    m_dataType->setReadOnly(true);
    general->addRow(tr("&Name:"), m_name);
    general->addRow(tr("Data type:"), m_dataType);
    m_connectDirection = new QComboBox;
    m_connectDirection->setObjectName(QStringLiteral("connectDirection"));
    for (ConnectDirection direction : choices.connectDirections)
        m_connectDirection->addItem(ConnectorSettings::directionText(direction),
                                    int(direction));
    m_directionChoices = int(choices.connectDirections.size());
    m_connectDirection->setToolTip(
        tr("Which port calls connect(); the system file records it as the connector's source."));
    general->addRow(tr("Connect &direction:"), m_connectDirection);

    auto *buffers = new QHBoxLayout;
    buffers->addWidget(buildBufferGroup(tr("OutPort buffer"), QStringLiteral("out"), m_outBuffer));
    buffers->addWidget(buildBufferGroup(tr("InPort buffer"), QStringLiteral("in"), m_inBuffer));

    m_problems = new QLabel;
    m_problems->setObjectName(QStringLiteral("problems"));
    m_problems->setStyleSheet(QStringLiteral("color: #b00020;"));
    m_problems->setWordWrap(true);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectorDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ConnectorDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(general);
    layout->addWidget(buildDataflowGroup(choices));
    layout->addLayout(buffers);
    layout->addWidget(buildFreeProperties());
    layout->addWidget(m_problems);
    layout->addWidget(m_buttons);

    for (QLineEdit *edit : findChildren<QLineEdit *>())
        connect(edit, &QLineEdit::textChanged, this, &ConnectorDialog::refresh);
    explainSettings();
    // An empty choice leaves the setting to the ports, as an empty buffer field does: say so alike.
    for (QComboBox *box : findChildren<QComboBox *>()) {
        if (box->isEditable() && box->itemText(0).isEmpty())
            box->lineEdit()->setPlaceholderText(tr("default"));
    }
    for (QComboBox *box : findChildren<QComboBox *>())
        connect(box, &QComboBox::currentTextChanged, this, &ConnectorDialog::refresh);
    connect(m_connectDirection, &QComboBox::currentIndexChanged, this, &ConnectorDialog::refresh);
}

QWidget *ConnectorDialog::buildDataflowGroup(const Choices &choices)
{
    auto *group = new QGroupBox(tr("Data flow"));
    auto *form = new QFormLayout(group);
    m_interfaceType = choiceBox(QStringLiteral("interfaceType"), choices.interfaceTypes);
    m_marshalingType = choiceBox(QStringLiteral("marshalingType"), choices.marshalingTypes, true);
    m_dataflowType = choiceBox(QStringLiteral("dataflowType"), choices.dataflowTypes);
    m_subscriptionType = choiceBox(QStringLiteral("subscriptionType"), choices.subscriptionTypes);
    m_pushRate = lineEdit(QStringLiteral("pushRate"));
    m_pushPolicy = choiceBox(QStringLiteral("pushPolicy"), ConnectorSettings::pushPolicies());
    m_skipCount = lineEdit(QStringLiteral("skipCount"));
    m_timestampPolicy = choiceBox(QStringLiteral("timestampPolicy"),
                                  ConnectorSettings::timestampPolicies(), true);
    form->addRow(tr("&Interface type:"), m_interfaceType);
    form->addRow(tr("&Marshaling type:"), m_marshalingType);
    form->addRow(tr("&Dataflow type:"), m_dataflowType);
    form->addRow(tr("&Subscription type:"), m_subscriptionType);
    form->addRow(tr("Push &rate (Hz):"), m_pushRate);
    form->addRow(tr("Push &policy:"), m_pushPolicy);
    form->addRow(tr("S&kip count:"), m_skipCount);
    form->addRow(tr("&Timestamp policy:"), m_timestampPolicy);
    return group;
}

// What's This (Shift+F1) on each setting: what it does, in a sentence or two. Keyed by the widget's
// object name; buffer settings apply to both buffers (object names with the "out" / "in" prefix).
void ConnectorDialog::explainSettings()
{
    static const struct
    {
        const char *name;
        const char *text;
    } explanations[] = {
        {"name", QT_TR_NOOP("The connector's name (rtctl con -n): the system file and the live ports know it by "
                            "this name; by default the two ports' names joined by '_'.")},
        {"connectDirection", QT_TR_NOOP("Which port calls connect(). The system file records that port as the "
                                        "connector's source; data flows from the OutPort either way.")},
        {"properties", QT_TR_NOOP("Properties without a field above, sent with the connector as they are (rtctl "
                                  "con -p KEY=VALUE): dataport.* settings of other connector types, or your "
                                  "own.")},
        {"interfaceType", QT_TR_NOOP("dataport.interface_type: how samples travel. corba_cdr sends them as CORBA "
                                     "calls between any two processes; other types need both sides to offer them.")},
        {"marshalingType", QT_TR_NOOP("dataport.marshaling_type: how samples are encoded on the way (cdr unless "
                                      "the components offer another serializer).")},
        {"dataflowType", QT_TR_NOOP("dataport.dataflow_type: push, the OutPort sends each sample as it is written; "
                                    "pull, the InPort asks for the latest sample when its component reads.")},
        {"subscriptionType", QT_TR_NOOP("dataport.subscription_type (push only): flush sends at once in the writer's "
                                        "thread; new sends the newest from a thread of the connector, skipping what "
                                        "it could not send yet; periodic sends at the push rate.")},
        {"pushRate", QT_TR_NOOP("dataport.push_rate: how many times a second a periodic subscription sends.")},
        {"pushPolicy", QT_TR_NOOP("dataport.publisher.push_policy: what each send takes from the OutPort buffer: "
                                  "all of it, the oldest (fifo), every n-th (skip) or the newest (new).")},
        {"skipCount", QT_TR_NOOP("dataport.publisher.skip_count: with the skip policy, how many samples are "
                                 "left out between two sent ones.")},
        {"timestampPolicy", QT_TR_NOOP("dataport.timestamp_policy: when a sample's time stamp is set: when it is "
                                       "written, sent, received or read.")},
        {"BufferLength", QT_TR_NOOP("buffer.length: how many samples the buffer holds.")},
        {"FullPolicy", QT_TR_NOOP("buffer.write.full_policy: what a write into a full buffer does: overwrite the "
                                  "oldest sample, do nothing (the sample is lost), or block until there is room "
                                  "or the write timeout passes.")},
        {"WriteTimeout", QT_TR_NOOP("buffer.write.timeout: how long a blocked write waits, in seconds.")},
        {"EmptyPolicy", QT_TR_NOOP("buffer.read.empty_policy: what a read from an empty buffer does: read the last "
                                   "sample again (readback), do nothing, or block until a sample comes or the "
                                   "read timeout passes.")},
        {"ReadTimeout", QT_TR_NOOP("buffer.read.timeout: how long a blocked read waits, in seconds.")},
    };
    for (QWidget *widget : findChildren<QWidget *>()) {
        const QString name = widget->objectName();
        for (const auto &explanation : explanations) {
            const QLatin1String key(explanation.name);
            if (name == key || name == QLatin1String("out") + key || name == QLatin1String("in") + key)
                widget->setWhatsThis(tr(explanation.text));
        }
    }
}

QGroupBox *ConnectorDialog::buildBufferGroup(const QString &title, const QString &prefix,
                                             BufferWidgets &widgets)
{
    auto *group = new QGroupBox(title);
    auto *form = new QFormLayout(group);
    widgets.length = lineEdit(prefix + QStringLiteral("BufferLength"));
    widgets.fullPolicy = choiceBox(prefix + QStringLiteral("FullPolicy"),
                                   ConnectorSettings::fullPolicies(), true);
    widgets.writeTimeout = lineEdit(prefix + QStringLiteral("WriteTimeout"));
    widgets.emptyPolicy = choiceBox(prefix + QStringLiteral("EmptyPolicy"),
                                    ConnectorSettings::emptyPolicies(), true);
    widgets.readTimeout = lineEdit(prefix + QStringLiteral("ReadTimeout"));
    for (QLineEdit *edit : {widgets.length, widgets.writeTimeout, widgets.readTimeout})
        edit->setPlaceholderText(tr("default"));
    form->addRow(tr("Length:"), widgets.length);
    form->addRow(tr("Full policy:"), widgets.fullPolicy);
    form->addRow(tr("Write timeout (s):"), widgets.writeTimeout);
    form->addRow(tr("Empty policy:"), widgets.emptyPolicy);
    form->addRow(tr("Read timeout (s):"), widgets.readTimeout);
    return group;
}

QWidget *ConnectorDialog::buildFreeProperties()
{
    auto *group = new QGroupBox(tr("Properties"));
    m_properties = new QTableWidget(0, 2);
    m_properties->setObjectName(QStringLiteral("properties"));
    m_properties->setHorizontalHeaderLabels({tr("Name"), tr("Value")});
    m_properties->horizontalHeader()->setStretchLastSection(true);
    m_properties->verticalHeader()->hide();
    m_properties->setMinimumHeight(90);
    connect(m_properties, &QTableWidget::itemChanged, this, &ConnectorDialog::refresh);
    auto *add = new QPushButton(tr("Add"));
    auto *remove = new QPushButton(tr("Remove"));
    connect(add, &QPushButton::clicked, this, [this] { addFreeProperty(); });
    connect(remove, &QPushButton::clicked, this, &ConnectorDialog::removeCurrentFreeProperty);
    auto *buttons = new QVBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    auto *layout = new QHBoxLayout(group);
    layout->addWidget(m_properties);
    layout->addLayout(buttons);
    return group;
}

void ConnectorDialog::setSettings(const ConnectorSettings &settings)
{
    m_filling = true;
    m_name->setText(settings.name);
    m_dataType->setText(settings.dataType);
    setChoice(m_interfaceType, settings.interfaceType);
    setChoice(m_marshalingType, settings.marshalingType);
    setChoice(m_dataflowType, settings.dataflowType);
    setChoice(m_subscriptionType, settings.subscriptionType);
    m_pushRate->setText(settings.pushRate);
    setChoice(m_pushPolicy, settings.pushPolicy);
    m_skipCount->setText(settings.skipCount);
    setChoice(m_timestampPolicy, settings.timestampPolicy);
    setDirection(settings.connectDirection);
    setBuffer(m_outBuffer, settings.outBuffer);
    setBuffer(m_inBuffer, settings.inBuffer);
    m_properties->setRowCount(0);
    for (const auto &[name, value] : settings.freeProperties)
        addFreeProperty(name, value);
    m_filling = false;
    refresh();
}

ConnectorSettings ConnectorDialog::settings() const
{
    ConnectorSettings s;
    s.name = m_name->text();
    s.dataType = m_dataType->text();
    s.interfaceType = m_interfaceType->currentText().trimmed();
    s.marshalingType = m_marshalingType->currentText().trimmed();
    s.dataflowType = m_dataflowType->currentText().trimmed();
    s.subscriptionType = m_subscriptionType->currentText().trimmed();
    s.pushRate = m_pushRate->text().trimmed();
    s.pushPolicy = m_pushPolicy->currentText().trimmed();
    s.skipCount = m_skipCount->text().trimmed();
    s.timestampPolicy = m_timestampPolicy->currentText().trimmed();
    s.connectDirection = m_connectDirection->currentIndex() < 0
        ? m_fixedDirection
        : ConnectDirection(m_connectDirection->currentData().toInt());
    s.outBuffer = buffer(m_outBuffer);
    s.inBuffer = buffer(m_inBuffer);
    s.freeProperties = freeProperties();
    return s;
}

void ConnectorDialog::setDirection(ConnectDirection direction)
{
    // A direction that is not offered is kept as it is (shown, not changeable).
    m_fixedDirection = direction;
    int index = m_connectDirection->findData(int(direction));
    if (index < 0) {
        m_connectDirection->addItem(ConnectorSettings::directionText(direction), int(direction));
        index = m_connectDirection->count() - 1;
    }
    m_connectDirection->setCurrentIndex(index);
}

void ConnectorDialog::setBuffer(const BufferWidgets &widgets, const BufferSettings &buffer)
{
    widgets.length->setText(buffer.length);
    setChoice(widgets.fullPolicy, buffer.fullPolicy);
    widgets.writeTimeout->setText(buffer.writeTimeout);
    setChoice(widgets.emptyPolicy, buffer.emptyPolicy);
    widgets.readTimeout->setText(buffer.readTimeout);
}

BufferSettings ConnectorDialog::buffer(const BufferWidgets &widgets) const
{
    BufferSettings b;
    b.length = widgets.length->text().trimmed();
    b.fullPolicy = widgets.fullPolicy->currentText().trimmed();
    b.writeTimeout = widgets.writeTimeout->text().trimmed();
    b.emptyPolicy = widgets.emptyPolicy->currentText().trimmed();
    b.readTimeout = widgets.readTimeout->text().trimmed();
    return b;
}

QList<QPair<QString, QString>> ConnectorDialog::freeProperties() const
{
    QList<QPair<QString, QString>> properties;
    for (int row = 0; row < m_properties->rowCount(); ++row) {
        const QTableWidgetItem *name = m_properties->item(row, 0);
        const QTableWidgetItem *value = m_properties->item(row, 1);
        properties.append({name ? name->text().trimmed() : QString(),
                           value ? value->text() : QString()});
    }
    return properties;
}

void ConnectorDialog::addFreeProperty(const QString &name, const QString &value)
{
    const int row = m_properties->rowCount();
    m_properties->insertRow(row);
    m_properties->setItem(row, 0, new QTableWidgetItem(name));
    m_properties->setItem(row, 1, new QTableWidgetItem(value));
    m_properties->setCurrentCell(row, 0);
    refresh();
}

void ConnectorDialog::removeCurrentFreeProperty()
{
    if (m_properties->currentRow() >= 0)
        m_properties->removeRow(m_properties->currentRow());
    refresh();
}

QStringList ConnectorDialog::problems() const
{
    return settings().validate();
}

void ConnectorDialog::refresh()
{
    if (m_filling)
        return;
    const ConnectorSettings s = settings();
    m_subscriptionType->setEnabled(s.isSubscriptionTypeEnabled());
    m_pushRate->setEnabled(s.isPushRateEnabled());
    m_pushPolicy->setEnabled(s.isPushPolicyEnabled());
    m_skipCount->setEnabled(s.isSkipCountEnabled());
    m_connectDirection->setEnabled(m_directionChoices > 1);
    const QStringList list = problems();
    m_problems->setText(list.join(QLatin1Char('\n')));
    m_problems->setVisible(!list.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(list.isEmpty());
}

void ConnectorDialog::accept()
{
    if (!problems().isEmpty())
        return;
    QDialog::accept();
}

} // namespace SystemEditor

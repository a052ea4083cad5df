// SPDX-License-Identifier: MIT
#include "configurationpage.h"

#include "componentrules.h"
#include "constraintsyntax.h"
#include "itemform.h"
#include "itemtablemodel.h"
#include "listeditor.h"

#include <QScrollArea>
#include <QSplitter>
#include <QVBoxLayout>

namespace Builder {

namespace {

using Profile::RtcConfiguration;
using Profile::RtcConfigurationDoc;

RtcConfiguration &configuration(PartItem &item)
{
    return std::get<RtcConfiguration>(item);
}

const RtcConfiguration &configuration(const PartItem &item)
{
    return std::get<RtcConfiguration>(item);
}

/// Stores `kind[.step]` as the `__widget__` property, or removes it when both are empty.
void setWidget(RtcConfiguration &c, const QString &kind, const QString &step)
{
    const QString value = step.isEmpty() ? kind : kind + QLatin1Char('.') + step;
    if (value.isEmpty()) {
        c.properties.removeIf([](const Profile::RtcProperty &p) {
            return p.name == RtcConfiguration::WidgetProperty;
        });
        return;
    }
    Profile::setRtcProperty(c.properties, RtcConfiguration::WidgetProperty, value);
}

ItemField constraintField()
{
    ItemField field;
    field.key = QStringLiteral("constraint");
    field.label = ConfigurationPage::tr("Constraint");
    field.get = [](const PartItem &item) {
        return Profile::constraintToString(configuration(item).constraint);
    };
    field.set = [](PartItem &item, const QString &text) {
        const Profile::ConstraintParseResult parsed = Profile::parseConstraintString(text);
        auto &constraint = configuration(item).constraint;
        // Text that means the tree already there keeps the tree (and what only the file has).
        if (parsed.ok()
            && Profile::constraintToString(constraint)
                != Profile::constraintToString(parsed.constraint))
            constraint = parsed.constraint;
    };
    field.check = [](const QString &text) {
        const Profile::ConstraintParseResult parsed = Profile::parseConstraintString(text);
        return parsed.ok()
            ? QString()
            : ConfigurationPage::tr("Constraint syntax: %1").arg(parsed.error->toString());
    };
    return field;
}

ItemField widgetField()
{
    ItemField field;
    field.key = QStringLiteral("widget");
    field.label = ConfigurationPage::tr("Widget");
    field.get = [](const PartItem &item) {
        return configuration(item).widget().value_or(QString()).section(QLatin1Char('.'), 0, 0);
    };
    field.set = [](PartItem &item, const QString &text) {
        RtcConfiguration &c = configuration(item);
        setWidget(c, text, c.widget().value_or(QString()).section(QLatin1Char('.'), 1));
    };
    field.choices = [] { return QStringList {QString()} + configurationWidgets(); };
    field.editableChoices = false;
    return field;
}

ItemField stepField()
{
    ItemField field;
    field.key = QStringLiteral("step");
    field.label = ConfigurationPage::tr("Step");
    field.get = [](const PartItem &item) {
        return configuration(item).widget().value_or(QString()).section(QLatin1Char('.'), 1);
    };
    field.set = [](PartItem &item, const QString &text) {
        RtcConfiguration &c = configuration(item);
        setWidget(c, c.widget().value_or(QString()).section(QLatin1Char('.'), 0, 0), text);
    };
    return field;
}

} // namespace

QStringList ConfigurationPage::typePresets()
{
    return {QStringLiteral("short"), QStringLiteral("int"),    QStringLiteral("long"),
            QStringLiteral("float"), QStringLiteral("double"), QStringLiteral("string")};
}

QList<ItemField> ConfigurationPage::columns()
{
    ItemField type
        = textField<RtcConfiguration>(QStringLiteral("type"), tr("Type"), &RtcConfiguration::type);
    type.choices = [] { return typePresets(); };
    return {
        textField<RtcConfiguration>(QStringLiteral("name"), tr("Name"), &RtcConfiguration::name),
        type,
        textField<RtcConfiguration>(QStringLiteral("defaultValue"), tr("Default value"),
                                    &RtcConfiguration::defaultValue),
        optionalTextField<RtcConfiguration>(QStringLiteral("variableName"), tr("Variable name"),
                                            &RtcConfiguration::variableName),
        optionalTextField<RtcConfiguration>(QStringLiteral("unit"), tr("Unit"),
                                            &RtcConfiguration::unit),
        constraintField(),
        widgetField(),
        stepField(),
    };
}

ConfigurationPage::ConfigurationPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
{
    auto *table = new ItemTableModel(model, undoStack, Part::Configuration, columns());
    const auto factory = [this]() -> PartItem {
        QStringList used;
        for (const RtcConfiguration &c : m_model->profile().configurations)
            used << c.name;
        RtcConfiguration c;
        c.name = uniqueName(QStringLiteral("param"), used);
        c.type = QStringLiteral("int");
        c.defaultValue = QStringLiteral("0");
        return c;
    };
    m_list = new ListEditor(model, undoStack, table, tr("Configuration parameters"), factory, this);

    m_form = new ItemForm(model, undoStack, Part::Configuration);
    m_form->addSection(tr("Parameter"));
    for (const ItemField &field : columns())
        m_form->addField(field);
    m_form->addSection(tr("Documentation"));
    const auto doc = [this](const char *key, const QString &label,
                            std::optional<QString> RtcConfigurationDoc::*member) {
        m_form->addField(docField<RtcConfiguration, RtcConfigurationDoc>(
            QLatin1String(key), label, &RtcConfiguration::doc, member));
    };
    doc("doc.dataname", tr("Data name"), &RtcConfigurationDoc::dataname);
    doc("doc.defaultValue", tr("Default value"), &RtcConfigurationDoc::defaultValue);
    doc("doc.description", tr("Description"), &RtcConfigurationDoc::description);
    doc("doc.unit", tr("Unit"), &RtcConfigurationDoc::unit);
    doc("doc.range", tr("Range"), &RtcConfigurationDoc::range);
    doc("doc.constraint", tr("Constraint"), &RtcConfigurationDoc::constraint);
    connect(m_list, &ListEditor::currentItemChanged, m_form, &ItemForm::setCurrentIndex);

    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setWidget(m_form);
    auto *splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_list);
    splitter->addWidget(scroll);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(splitter);
}

} // namespace Builder

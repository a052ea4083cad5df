// SPDX-License-Identifier: MIT
#pragma once

#include "connectorsettings.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace SystemEditor {

/**
 * The data connector dialog: every field of the reference's dialog (ConnectorSettings), with
 * its enabling rules (subscription type only for push, push rate only for periodic, push policy
 * only for new/periodic, skip count only for the skip policy, connect direction only when both
 * directions are offered) and its validation shown live; OK stays disabled while there is a
 * problem.
 *
 * Used both for a new connector (filled with ConnectorSettings::defaults()) and for editing an
 * existing one. Widgets carry object names (`name`, `dataflowType`, `pushRate`, …) so that tests
 * and scripts can drive the dialog.
 */
class ConnectorDialog : public QDialog
{
    Q_OBJECT

public:
    /// The choices offered in the combo boxes (by default ConnectorSettings' lists).
    struct Choices
    {
        QStringList interfaceTypes = ConnectorSettings::interfaceTypes();
        QStringList dataflowTypes = ConnectorSettings::dataflowTypes();
        QStringList subscriptionTypes = ConnectorSettings::subscriptionTypes();
        QStringList marshalingTypes {QStringLiteral("cdr")};
        /// Who may call connect(); the field is enabled only when there is a choice (a live
        /// connection that exists already cannot turn around).
        QList<ConnectDirection> connectDirections {ConnectDirection::OutToIn,
                                                   ConnectDirection::InToOut};
    };

    explicit ConnectorDialog(const ConnectorSettings &settings, QWidget *parent = nullptr);
    ConnectorDialog(const ConnectorSettings &settings, const Choices &choices,
                    QWidget *parent = nullptr);

    /// The fields as they are now.
    ConnectorSettings settings() const;
    void setSettings(const ConnectorSettings &settings);
    /// What keeps the dialog from being accepted (ConnectorSettings::validate()).
    QStringList problems() const;

    /// Free properties: appends a row / removes the current one.
    void addFreeProperty(const QString &name = {}, const QString &value = {});
    void removeCurrentFreeProperty();

    void accept() override;

private:
    struct BufferWidgets
    {
        QLineEdit *length;
        QComboBox *fullPolicy;
        QLineEdit *writeTimeout;
        QComboBox *emptyPolicy;
        QLineEdit *readTimeout;
    };

    void buildForm(const Choices &choices);
    QWidget *buildDataflowGroup(const Choices &choices);
    void explainSettings();
    QGroupBox *buildBufferGroup(const QString &title, const QString &prefix,
                                BufferWidgets &widgets);
    QWidget *buildFreeProperties();
    void setDirection(ConnectDirection direction);
    void setBuffer(const BufferWidgets &widgets, const BufferSettings &buffer);
    BufferSettings buffer(const BufferWidgets &widgets) const;
    QList<QPair<QString, QString>> freeProperties() const;
    void refresh();

    QLineEdit *m_name = nullptr;
    QLineEdit *m_dataType = nullptr;
    QComboBox *m_interfaceType = nullptr;
    QComboBox *m_marshalingType = nullptr;
    QComboBox *m_dataflowType = nullptr;
    QComboBox *m_subscriptionType = nullptr;
    QLineEdit *m_pushRate = nullptr;
    QComboBox *m_pushPolicy = nullptr;
    QLineEdit *m_skipCount = nullptr;
    QComboBox *m_timestampPolicy = nullptr;
    QComboBox *m_connectDirection = nullptr;
    ConnectDirection m_fixedDirection = ConnectDirection::OutToIn;
    int m_directionChoices = 0;
    BufferWidgets m_outBuffer {};
    BufferWidgets m_inBuffer {};
    QTableWidget *m_properties = nullptr;
    QLabel *m_problems = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    bool m_filling = false;
};

} // namespace SystemEditor

// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QComboBox;
class QLineEdit;

namespace Builder {

/**
 * Build Settings: the SDK prefix handed to CMake as CMAKE_PREFIX_PATH (where OpenRTM-aist or
 * RT Studio's SDK is installed; empty: none) with Browse… and Default, and the build type.
 */
class BuildSettingsDialog : public QDialog
{
    Q_OBJECT

public:
    BuildSettingsDialog(const QString &sdkPrefix, const QString &defaultPrefix,
                        const QString &buildType, QWidget *parent = nullptr);

    QString sdkPrefix() const;
    QString buildType() const;
    QLineEdit *prefixEdit() const { return m_prefix; }
    QComboBox *buildTypeBox() const { return m_buildType; }

private:
    void browse();

    QLineEdit *m_prefix;
    QComboBox *m_buildType;
};

} // namespace Builder

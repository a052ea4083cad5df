// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "document.h"

namespace Studio {

/**
 * An open RTC Profile (a component, as RTC Builder edits it): the file, its format and its undo
 * history around the Builder's editing model, which holds the profile and announces every change.
 */
class RtcDocument : public Document
{
    Q_OBJECT

public:
    explicit RtcDocument(Profile::RtcProfile profile, QObject *parent = nullptr);

    Profile::ProfileKind kind() const override { return Profile::ProfileKind::Rtc; }
    const Profile::RtcProfile &profile() const { return m_model->profile(); }
    QByteArray serialize(Profile::FileFormat format) const override;

    /// The editing model; commands and editor pages work on it.
    Builder::ComponentModel *model() const { return m_model; }

private:
    Builder::ComponentModel *m_model;
};

} // namespace Studio

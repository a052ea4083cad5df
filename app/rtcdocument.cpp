// SPDX-License-Identifier: MIT
#include "rtcdocument.h"

namespace Studio {

RtcDocument::RtcDocument(Profile::RtcProfile profile, QObject *parent)
    : Document(parent)
    , m_model(new Builder::ComponentModel(std::move(profile), this))
{ }

QByteArray RtcDocument::serialize(Profile::FileFormat format) const
{
    return Profile::serializeRtcProfile(m_model->profile(), format);
}

} // namespace Studio

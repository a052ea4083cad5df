// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Profile::Ns {

/// Namespace URIs of the RTC and RTS Profile schemas (OpenRTP), matched by URI, never by prefix.
inline const QString Rtc = QStringLiteral("http://www.openrtp.org/namespaces/rtc");
inline const QString RtcDoc = QStringLiteral("http://www.openrtp.org/namespaces/rtc_doc");
inline const QString RtcExt = QStringLiteral("http://www.openrtp.org/namespaces/rtc_ext");
inline const QString Rts = QStringLiteral("http://www.openrtp.org/namespaces/rts");
inline const QString RtsExt = QStringLiteral("http://www.openrtp.org/namespaces/rts_ext");
inline const QString Xsi = QStringLiteral("http://www.w3.org/2001/XMLSchema-instance");

/// The prefix OpenRTP writes for a known namespace URI; empty for an unknown one.
QString preferredPrefix(const QString &uri);

} // namespace Profile::Ns

// SPDX-License-Identifier: MIT
// librtstudio_client: the static libraries' objects make the library; this file gives it its
// version, for programs that want to know which one they loaded.
#include <QtGlobal>

extern "C" Q_DECL_EXPORT const char *rtstudio_client_version()
{
    return RTSTUDIO_VERSION;
}

// SPDX-License-Identifier: MIT
#pragma once

#include <SDOPackage.hh>

#include <QByteArray>
#include <QString>

/// The string value of @p name in an SDO name/value list; empty when absent or not a string.
inline QString nv(const SDOPackage::NVList &list, const char *name)
{
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        const char *text = nullptr;
        if (QByteArray(list[i].name) == name && (list[i].value >>= text))
            return QString::fromUtf8(text);
    }
    return {};
}

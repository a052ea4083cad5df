// SPDX-License-Identifier: MIT
#pragma once

// Reads what a component publishes in its SDO status list (the built-in sinks report the data
// they received there), for tests that watch data flow from outside.

#include <RTC.hh>

#include <QByteArray>
#include <QList>
#include <QString>

namespace LiveTest {

/// The string status @p name of the component at @p ior (an IOR, corbaloc or corbaname);
/// empty when it is unreachable or has no such status.
inline QString componentStatus(CORBA::ORB_ptr orb, const QString &ior, const char *name)
{
    try {
        CORBA::Object_var object = orb->string_to_object(ior.toUtf8().constData());
        RTC::RTObject_var rtc = RTC::RTObject::_narrow(object);
        SDOPackage::NVList_var list = rtc->get_status_list();
        for (CORBA::ULong i = 0; i < list->length(); ++i) {
            const char *text = nullptr;
            if (QByteArray(list[i].name.in()) == name && (list[i].value >>= text))
                return QString::fromUtf8(text);
        }
    } catch (const CORBA::Exception &) {
    }
    return {};
}

/// The values of a status that lists integers with commas (ConsoleOut's `received_values`).
inline QList<qint64> integers(const QString &text)
{
    QList<qint64> values;
    for (const QString &item : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
        values << item.toLongLong();
    return values;
}

} // namespace LiveTest

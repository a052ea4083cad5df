// SPDX-License-Identifier: MIT
/*!
 * @file utils.h
 * @brief Stream output of SDO name-value lists and configuration sets, for printing profiles.
 */
#ifndef HRTM_UTILS_H
#define HRTM_UTILS_H

#include <rtm/RTC.h>

#include <iostream>

// HRTM code relies on this header bringing the standard names in (cout, endl, ostream).
using namespace std;

namespace hrtm {
/*! "name:<name>" and "value:<text>" lines (values that are not strings are marked). */
inline ostream &operator<<(ostream &os, const SDOPackage::NameValue &nv)
{
    os << "name:" << nv.name << endl;
    const char *text = 0;
    os << "value:";
    if (nv.value >>= text)
        os << text << endl;
    else
        os << "<<<NO PRINTABLE>>>" << endl;
    return os;
}

/*! Every entry of @p nvlist, as above. */
inline ostream &operator<<(ostream &os, const SDOPackage::NVList &nvlist)
{
    for (CORBA::ULong i = 0; i < nvlist.length(); ++i)
        os << nvlist[i];
    return os;
}

/*! The set's id, description and values between begin and end markers. */
inline ostream &operator<<(ostream &os, const SDOPackage::ConfigurationSet &cs)
{
    os << "---[BEGIN ConfigurationSet]---" << endl;
    os << "id:" << cs.id << endl;
    os << "description:" << cs.description << endl;
    os << "configuration_data:" << endl;
    os << cs.configuration_data << endl;
    os << "---[END   ConfigurationSet]---" << endl;
    return os;
}
} // namespace hrtm

#endif // HRTM_UTILS_H

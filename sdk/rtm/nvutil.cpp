// SPDX-License-Identifier: MIT
#include <rtm/NVUtil.h>

#include <coil/stringutil.h>

#include <algorithm>
#include <cstring>
#include <sstream>

namespace NVUtil {

namespace {

// Any extraction of a string leaves the pointer owned by the Any; nullptr when it is no string.
const char *stringIn(const CORBA::Any &value)
{
    const char *text = nullptr;
    if (!(value >>= text))
        return nullptr;
    return text;
}

void setString(SDOPackage::NameValue &entry, const std::string &name, const std::string &value)
{
    entry.name = CORBA::string_dup(name.c_str());
    entry.value <<= value.c_str();
}

} // namespace

SDOPackage::NameValue newNVChar(const char *name, CORBA::Char value)
{
    return newNV(name, CORBA::Any::from_char(value));
}

SDOPackage::NameValue newNVBool(const char *name, CORBA::Boolean value)
{
    return newNV(name, CORBA::Any::from_boolean(value));
}

SDOPackage::NameValue newNVOctet(const char *name, CORBA::Octet value)
{
    return newNV(name, CORBA::Any::from_octet(value));
}

SDOPackage::NameValue newNVAny(const char *name, const CORBA::Any &value)
{
    SDOPackage::NameValue entry;
    entry.name = CORBA::string_dup(name);
    entry.value = value;
    return entry;
}

void copyFromProperties(SDOPackage::NVList &nv, const coil::Properties &prop)
{
    const std::vector<std::string> keys = prop.propertyNames();
    nv.length(CORBA::ULong(keys.size()));
    for (CORBA::ULong i = 0; i < nv.length(); ++i)
        setString(nv[i], keys[i], prop.getProperty(keys[i]));
}

void mergeFromProperties(SDOPackage::NVList &nv, const coil::Properties &prop)
{
    const std::vector<std::string> keys = prop.propertyNames();
    SDOPackage::NVList kept;
    for (CORBA::ULong i = 0; i < nv.length(); ++i) {
        const char *name = nv[i].name;
        if (std::find(keys.begin(), keys.end(), std::string(name)) == keys.end()) {
            kept.length(kept.length() + 1);
            kept[kept.length() - 1] = nv[i];
        }
    }
    nv.length(CORBA::ULong(keys.size()) + kept.length());
    CORBA::ULong at = 0;
    for (const std::string &key : keys)
        setString(nv[at++], key, prop.getProperty(key));
    for (CORBA::ULong i = 0; i < kept.length(); ++i)
        nv[at++] = kept[i];
}

void copyToProperties(coil::Properties &prop, const SDOPackage::NVList &nv)
{
    for (CORBA::ULong i = 0; i < nv.length(); ++i) {
        if (const char *value = stringIn(nv[i].value))
            prop.setProperty(static_cast<const char *>(nv[i].name), value);
    }
}

coil::Properties toProperties(const SDOPackage::NVList &nv)
{
    coil::Properties prop;
    copyToProperties(prop, nv);
    return prop;
}

const CORBA::Any &find(const SDOPackage::NVList &nv, const char *name)
{
    const CORBA::Long index = find_index(nv, name);
    if (index < 0)
        throw std::string("Not found");
    return nv[CORBA::ULong(index)].value;
}

CORBA::Long find_index(const SDOPackage::NVList &nv, const char *name)
{
    for (CORBA::ULong i = 0; i < nv.length(); ++i) {
        if (std::strcmp(nv[i].name, name) == 0)
            return CORBA::Long(i);
    }
    return -1;
}

bool isString(const SDOPackage::NVList &nv, const char *name)
{
    const CORBA::Long index = find_index(nv, name);
    return index >= 0 && stringIn(nv[CORBA::ULong(index)].value) != nullptr;
}

bool isStringValue(const SDOPackage::NVList &nv, const char *name, const char *value)
{
    return isString(nv, name) && toString(nv, name) == value;
}

std::string toString(const SDOPackage::NVList &nv, const char *name)
{
    const CORBA::Long index = find_index(nv, name);
    if (index < 0)
        return {};
    const char *value = stringIn(nv[CORBA::ULong(index)].value);
    return value ? std::string(value) : std::string();
}

bool appendStringValue(SDOPackage::NVList &nv, const char *name, const char *value)
{
    const CORBA::Long index = find_index(nv, name);
    if (index < 0) {
        nv.length(nv.length() + 1);
        setString(nv[nv.length() - 1], name, value);
        return true;
    }
    SDOPackage::NameValue &entry = nv[CORBA::ULong(index)];
    const char *current = stringIn(entry.value);
    std::string joined = current ? current : "";
    const coil::vstring listed = coil::split(joined, ",");
    if (std::find(listed.begin(), listed.end(), std::string(value)) == listed.end()) {
        // An entry that held no string yet becomes the one value, not ",value".
        joined = current ? joined + "," + value : std::string(value);
        entry.value <<= joined.c_str();
    }
    return true;
}

void append(SDOPackage::NVList &dest, const SDOPackage::NVList &src)
{
    const CORBA::ULong start = dest.length();
    dest.length(start + src.length());
    for (CORBA::ULong i = 0; i < src.length(); ++i)
        dest[start + i] = src[i];
}

std::ostream &dump_to_stream(std::ostream &out, const SDOPackage::NameValue &nv)
{
    const char *value = stringIn(nv.value);
    out << static_cast<const char *>(nv.name) << ": " << (value ? value : "not a string value")
        << std::endl;
    return out;
}

std::ostream &operator<<(std::ostream &os, const SDOPackage::NameValue &nv)
{
    return dump_to_stream(os, nv);
}

std::ostream &operator<<(std::ostream &os, const SDOPackage::NVList &nvlist)
{
    return dump(os, nvlist);
}

std::ostream &dump(std::ostream &out, const SDOPackage::NVList &nv)
{
    for (CORBA::ULong i = 0; i < nv.length(); ++i)
        dump_to_stream(out, nv[i]);
    return out;
}

void dump(const SDOPackage::NVList &nv)
{
    dump(std::cout, nv);
}

std::string toString(const SDOPackage::NVList &nv)
{
    std::ostringstream text;
    dump(text, nv);
    return text.str();
}

} // namespace NVUtil

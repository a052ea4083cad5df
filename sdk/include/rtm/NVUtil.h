// SPDX-License-Identifier: MIT
// Helpers for SDO name/value lists (SDOPackage::NVList): building entries, converting to and from
// coil::Properties, looking values up and printing them, with OpenRTM-aist's names and semantics.
#ifndef NVUTIL_NVUTIL_H
#define NVUTIL_NVUTIL_H

#include <coil/Properties.h>
#include <rtm/idl/SDOPackageSkel.h>

#include <iostream>
#include <string>

namespace NVUtil
{
/// A name/value entry whose value is `value` inserted into a CORBA::Any.
template <class Value>
SDOPackage::NameValue newNV(const char *name, Value value)
{
    SDOPackage::NameValue entry;
    entry.name = CORBA::string_dup(name);
    entry.value <<= value;
    return entry;
}

/// newNV() for the IDL types whose Any insertion needs a wrapper (char, boolean, octet).
SDOPackage::NameValue newNVChar(const char *name, CORBA::Char value);
SDOPackage::NameValue newNVBool(const char *name, CORBA::Boolean value);
SDOPackage::NameValue newNVOctet(const char *name, CORBA::Octet value);
/// An entry holding a copy of `value` as it is.
SDOPackage::NameValue newNVAny(const char *name, const CORBA::Any &value);

/// Replaces `nv` with one string entry for each leaf key of `prop` (full dotted key as name).
void copyFromProperties(SDOPackage::NVList &nv, const coil::Properties &prop);
/// Puts `prop`'s keys first (as strings) and keeps those entries of `nv` that `prop` lacks.
void mergeFromProperties(SDOPackage::NVList &nv, const coil::Properties &prop);
/// Sets `prop[name] = value` for each entry of `nv` holding a string; other entries are skipped.
void copyToProperties(coil::Properties &prop, const SDOPackage::NVList &nv);
/// The string entries of `nv` as properties.
coil::Properties toProperties(const SDOPackage::NVList &nv);

/**
 * The value of the first entry called `name`.
 * @throws std::string ("Not found") when there is none, as OpenRTM-aist does.
 */
const CORBA::Any &find(const SDOPackage::NVList &nv, const char *name);
/// The index of the first entry called `name`, or -1.
CORBA::Long find_index(const SDOPackage::NVList &nv, const char *name);
/// Whether an entry called `name` exists and holds a string.
bool isString(const SDOPackage::NVList &nv, const char *name);
/// Whether the entry called `name` holds the string `value`.
bool isStringValue(const SDOPackage::NVList &nv, const char *name, const char *value);
/// The string held by the entry called `name`; empty when missing or not a string.
std::string toString(const SDOPackage::NVList &nv, const char *name);
/**
 * Adds `value` to the comma-separated string of the entry called `name` unless it is listed
 * there already; adds the entry when there is none. Always returns true.
 */
bool appendStringValue(SDOPackage::NVList &nv, const char *name, const char *value);
/// Appends every entry of `src` to `dest`.
void append(SDOPackage::NVList &dest, const SDOPackage::NVList &src);

/// Writes "name: value" and a newline ("name: not a string value" for non-strings).
std::ostream &dump_to_stream(std::ostream &out, const SDOPackage::NameValue &nv);
std::ostream &operator<<(std::ostream &os, const SDOPackage::NameValue &nv);
std::ostream &operator<<(std::ostream &os, const SDOPackage::NVList &nvlist);
/// Writes every entry of `nv` to `out`, one line each.
std::ostream &dump(std::ostream &out, const SDOPackage::NVList &nv);
/// Writes every entry of `nv` to standard output.
void dump(const SDOPackage::NVList &nv);
/// What dump() writes, as a string.
std::string toString(const SDOPackage::NVList &nv);
} // namespace NVUtil

#endif // NVUTIL_NVUTIL_H

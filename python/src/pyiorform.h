// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonValue>

#include <string>

namespace RtPython {

/**
 * Object references in the form the IDL value converter and Codegen::CdrCodec carry them
 * (`{"type_id": …, "profiles": [{"tag": …, "data": hex}]}`, null when nil) and as stringified IORs
 * (`IOR:` and the hex of a CDR encapsulation), both ways: what turns a callable reference passed
 * to a call into the value the codec marshals, and a received one into a reference to call.
 */
namespace IorForm {

/// The converter's form of the stringified IOR @p ior; null for a nil one. Throws std::runtime_error
/// when @p ior is no IOR.
QJsonValue fromIor(const std::string &ior);
/// The stringified IOR (little-endian encapsulation) of the converter's form @p reference.
std::string toIor(const QJsonValue &reference);

} // namespace IorForm

} // namespace RtPython

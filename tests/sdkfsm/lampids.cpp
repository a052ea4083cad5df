// SPDX-License-Identifier: MIT
// The lamp's state identifiers (each Macho state class gets one, once).
#include "lampmachine.h"

template <>
const ::Macho::ID Macho::StateID<Lamp::Top>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;
template <>
const ::Macho::ID Macho::StateID<Lamp::Off>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;
template <>
const ::Macho::ID Macho::StateID<Lamp::On>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;
template <>
const ::Macho::ID Macho::StateID<Lamp::Dim>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;
template <>
const ::Macho::ID Macho::StateID<Lamp::Bright>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;
template <>
const ::Macho::ID Macho::StateID<Lamp::Warm>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;
template <>
const ::Macho::ID Macho::StateID<Lamp::Cold>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;
template <>
const ::Macho::ID Macho::StateID<Lamp::Broken>::value = ::Macho::Machine<Lamp::Top>::theStateCount++;

// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "namingbrowser.h"

#include <QColor>
#include <QIcon>

namespace SystemEditor {

/// Icons and colours shared by the online views, drawn in code so they need no resource files.
namespace OnlineIcons {

/// The state colours of OpenRTP: Created white, Inactive blue, Active green, Error red,
/// Unknown (or unreachable) black.
QColor stateColor(Corba::LifeCycleState state);
/// A component icon filled with its state colour.
QIcon component(Corba::LifeCycleState state);
/// The icon of a name-service node of another type.
QIcon node(Corba::NodeType type);

/// A component state as the views show it, in the GUI's language (rtshell's words in English).
QString stateLabel(Corba::LifeCycleState state);
/// The kind of a name-service node as the views show it, in the GUI's language.
QString nodeTypeLabel(Corba::NodeType type);

} // namespace OnlineIcons

} // namespace SystemEditor

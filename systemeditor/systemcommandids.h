// SPDX-License-Identifier: MIT
#pragma once

namespace SystemEditor {

/// QUndoCommand::id() values of the System Editor's commands; equal ids may merge.
enum CommandId : int {
    MoveComponentsCommandId = 3001,
    ResizeComponentCommandId,
    BendPointsCommandId,
    SystemInfoCommandId,
    ConfigurationValueCommandId,
};

} // namespace SystemEditor

// SPDX-License-Identifier: MIT
#pragma once

namespace Builder {

/// QUndoCommand::id() values of the Builder's commands; equal ids may merge (see mergeWith()).
enum CommandId : int {
    BasicFieldCommandId = 1001,
    ActionCommandId = 1002,
    ComponentDocCommandId = 1003,
    LanguageCommandId = 1004,
    EditItemCommandId = 1005,
};

} // namespace Builder

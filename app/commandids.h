// SPDX-License-Identifier: MIT
#pragma once

namespace Studio {

/// QUndoCommand::id() values; commands with the same id may merge (see mergeWith()).
enum CommandId : int {
    SystemInfoCommandId = 2001,
};

} // namespace Studio

// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Templates {

/// The resource folder holding the built-in template folders (`common/`, `cpp/`, `python/`,
/// `java/`), each with its `manifest.json`. Ends with `/`.
QString builtinRoot();

} // namespace Templates

// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "profileio.h"

#include <memory>

class QObject;
class QString;

namespace Studio {

class Document;

/**
 * Reads an RTC or RTS profile (XML or YAML, detected by content) into a new document of the
 * matching kind. On failure returns null and appends the reasons (`FILE:LINE:COL`) to
 * `diagnostics`; the reader's warnings of a successful load are kept in the document.
 */
std::unique_ptr<Document> loadDocument(const QString &path, Profile::Diagnostics *diagnostics);

/// The document of a profile Profile::loadProfileFile() read from @p path (null when it is neither kind).
std::unique_ptr<Document> documentFromProfile(Profile::LoadedProfile loaded, const QString &path,
                                              Profile::Diagnostics *diagnostics);

} // namespace Studio

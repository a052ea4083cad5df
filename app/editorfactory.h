// SPDX-License-Identifier: MIT
#pragma once

class QWidget;

namespace Studio {

class Document;

/// The editor widget for a document of either kind (Builder::ComponentEditor or RtsEditor).
QWidget *createEditor(Document *document, QWidget *parent = nullptr);

} // namespace Studio

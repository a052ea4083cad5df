// SPDX-License-Identifier: MIT
#pragma once

class QWidget;

namespace Studio {

class Document;

/// The editor widget for a document of either kind (Builder::ComponentEditor, RtsEditor, or the
/// SystemEditor::OnlineDiagram of an OnlineDocument).
QWidget *createEditor(Document *document, QWidget *parent = nullptr);

} // namespace Studio

// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QAction;
class QTextBrowser;

namespace Studio {

/**
 * The user guide inside the program: README.md and the pages of docs/ (built into the program as
 * resources, so an installation always has the guide of its own version), rendered by
 * QTextBrowser's Markdown support. Links between pages are followed in the window; links to the web
 * open in the desktop's browser. Japanese pages (docs/ja/) are shown first when the GUI is Japanese.
 */
class UserGuide : public QWidget
{
    Q_OBJECT

public:
    /// The guide's pages: README.md and docs/… below this resource folder.
    static inline const QString Root = QStringLiteral(":/guide/");

    explicit UserGuide(QWidget *parent = nullptr);

    /// The page @p name (e.g. "getting-started.md") in @p language ("en" or "ja"): the Japanese one
    /// when there is one, else the English one; empty when there is neither.
    static QString page(const QString &name, const QString &language);

    /// Shows @p name in @p language (see page()).
    void showPage(const QString &name, const QString &language);
    /// Shows @p name scrolled to its heading @p section (its text, e.g. "Builder"); the top of the
    /// page when it has no such heading.
    void showSection(const QString &name, const QString &section, const QString &language);
    /// The text of the heading shown at the top of the window; empty when none is.
    QString sectionAtTop() const;

    QTextBrowser *browser() const { return m_browser; }

protected:
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void scrollToPendingSection();
    void fitPictures();

    QTextBrowser *m_browser;
    QString m_pendingSection;
    QAction *m_back;
    QAction *m_forward;
};

} // namespace Studio

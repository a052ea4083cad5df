// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QObject>

#include <functional>

class QCoreApplication;
class QWidget;

namespace GuiTest {

/**
 * Fails the running test at once when a modal dialog opens that the test does not expect, with
 * the dialog's title and text, and rejects that dialog so the test goes on instead of waiting for
 * an answer nobody gives.
 *
 * Every test executable that uses Qt Widgets has one, installed when its QApplication starts
 * (tests/CMakeLists.txt links it in); tests never create it. A test that makes the code under
 * test open a modal dialog (QDialog::exec(), QDialog::open(), the QMessageBox and QFileDialog
 * functions) declares it with an Expected.
 */
class ModalGuard : public QObject
{
    Q_OBJECT

public:
    /// What a test does with an expected dialog once it is up.
    using Answer = std::function<void(QWidget *dialog)>;

    /**
     * One modal dialog the test expects while this object lives. Several are matched to the
     * dialogs in the order they were declared.
     */
    class Expected
    {
    public:
        /// @p answer runs on the dialog once it is up, from inside the dialog's own event loop.
        /// Without one the test answers the dialog itself (one opened with QDialog::open()).
        explicit Expected(Answer answer = {});
        ~Expected();
        Expected(const Expected &) = delete;
        Expected &operator=(const Expected &) = delete;

        /// True once the dialog opened.
        bool seen() const { return m_seen; }

    private:
        friend class ModalGuard;
        Answer m_answer;
        bool m_seen = false;
    };

    ~ModalGuard() override;

    /// Starts watching @p app's windows; called once when the application starts.
    static void install(QCoreApplication *app);

    /// How the guard names a dialog: its class, title and text (a message box's informative
    /// text too; for other dialogs the texts of their labels).
    static QString describe(const QWidget *dialog);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    explicit ModalGuard(QObject *parent);
    void modalShown(QWidget *dialog);
    void reject(QWidget *dialog);

    QList<Expected *> m_expected;
};

} // namespace GuiTest

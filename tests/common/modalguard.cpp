// SPDX-License-Identifier: MIT
#include "modalguard.h"

#include <QCoreApplication>
#include <QDialog>
#include <QEvent>
#include <QLabel>
#include <QMessageBox>
#include <QTest>

namespace GuiTest {

namespace {

ModalGuard *guard = nullptr;

void installOnApplication()
{
    ModalGuard::install(QCoreApplication::instance());
}

} // namespace

// Runs in every test executable this file is linked into, as soon as its application exists, so
// no test can forget the guard.
Q_COREAPP_STARTUP_FUNCTION(installOnApplication)

ModalGuard::Expected::Expected(Answer answer)
    : m_answer(std::move(answer))
{
    if (guard)
        guard->m_expected.append(this);
}

ModalGuard::Expected::~Expected()
{
    if (guard)
        guard->m_expected.removeOne(this);
}

ModalGuard::ModalGuard(QObject *parent)
    : QObject(parent)
{ }

ModalGuard::~ModalGuard()
{
    guard = nullptr;
}

void ModalGuard::install(QCoreApplication *app)
{
    if (guard || !app)
        return;
    guard = new ModalGuard(app);
    app->installEventFilter(guard);
}

QString ModalGuard::describe(const QWidget *dialog)
{
    QStringList texts;
    if (const auto *box = qobject_cast<const QMessageBox *>(dialog)) {
        texts << box->text() << box->informativeText();
    } else {
        for (const QLabel *label : dialog->findChildren<QLabel *>())
            texts << label->text();
    }
    texts.removeAll(QString());
    return QStringLiteral("%1 \"%2\": %3")
        .arg(QString::fromLatin1(dialog->metaObject()->className()), dialog->windowTitle(),
             texts.join(QStringLiteral(" / ")));
}

bool ModalGuard::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Show && watched->isWidgetType()) {
        auto *widget = static_cast<QWidget *>(watched);
        if (widget->isWindow() && widget->isModal())
            modalShown(widget);
    }
    return false;
}

void ModalGuard::modalShown(QWidget *dialog)
{
    for (Expected *expected : std::as_const(m_expected)) {
        if (expected->m_seen)
            continue;
        expected->m_seen = true;
        if (expected->m_answer) {
            // Queued: an exec()'d dialog takes events only once its own loop runs.
            QMetaObject::invokeMethod(
                dialog,
                [this, expected, dialog] {
                    if (m_expected.contains(expected))
                        expected->m_answer(dialog);
                },
                Qt::QueuedConnection);
        }
        return;
    }
    const QString message = QStringLiteral("Unexpected modal dialog (a test declares the dialogs "
                                           "it expects with GuiTest::ModalGuard::Expected): ")
        + describe(dialog);
    if (!QTest::currentTestFunction())
        qFatal("%s", qPrintable(message)); // no test to fail: the process itself does
    QTest::qFail(qPrintable(message), __FILE__, __LINE__);
    reject(dialog);
}

void ModalGuard::reject(QWidget *dialog)
{
    // Queued like an answer; dropped with the dialog if the code under test deletes it first.
    QMetaObject::invokeMethod(
        dialog,
        [dialog] {
            if (auto *modal = qobject_cast<QDialog *>(dialog))
                modal->reject();
            else
                dialog->close();
        },
        Qt::QueuedConnection);
}

} // namespace GuiTest

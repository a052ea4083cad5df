// SPDX-License-Identifier: MIT
#pragma once

#include <QDeadlineTimer>

class QObject;
class QThread;

namespace Corba {

/**
 * Ends a worker thread that may be inside remote calls: asks it to quit and waits until
 * @p deadline. A thread that still runs then (its call ends with the call timeout) is not
 * destroyed while running, which would abort the program: it is left to finish on its own, and
 * @p worker (living in it) and the thread object are deleted once it has. Call quit() on all
 * threads first and give them one deadline, so that several hung peers cost one wait.
 */
void retireWorkerThread(QThread *thread, QObject *worker, QDeadlineTimer deadline);

} // namespace Corba

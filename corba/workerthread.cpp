// SPDX-License-Identifier: MIT
#include "workerthread.h"

#include <QThread>

namespace Corba {

void retireWorkerThread(QThread *thread, QObject *worker, QDeadlineTimer deadline)
{
    thread->quit();
    if (thread->wait(deadline)) {
        delete worker;
        delete thread;
        return;
    }
    // The worker's thread has no event loop left: a deferred delete runs when the thread ends.
    worker->deleteLater();
    QObject::connect(thread, &QThread::finished, thread, &QObject::deleteLater);
}

} // namespace Corba

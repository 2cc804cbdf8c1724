// SPDX-License-Identifier: GPL-3.0-or-later
#include "stopbeforeexit.h"

#include "rotatorsession.h"
#include "transport/link.h"

#include <QIODevice>
#include <QTimer>

#include <memory>

namespace slew::session {

namespace {
constexpr int kFlushGiveUpMs = 1000;
}

bool stopThenCall(RotatorSession &session, QObject *context, std::function<void()> done)
{
    const bool stopped = session.link() && session.stop();
    transport::Link *link = session.link();
    QIODevice *device = link ? link->device() : nullptr;
    if (!device || device->bytesToWrite() == 0) {
        QTimer::singleShot(0, context, std::move(done));
        return stopped;
    }
    // Wait for the stop to leave, from the event loop, with a limit.
    auto once = std::make_shared<std::function<void()>>(std::move(done));
    auto finish = [once] {
        if (!*once)
            return;
        auto call = std::move(*once);
        *once = nullptr;
        call();
    };
    QObject::connect(device, &QIODevice::bytesWritten, context, [device, finish](qint64) {
        if (device->bytesToWrite() == 0)
            finish();
    });
    QTimer::singleShot(kFlushGiveUpMs, context, finish);
    return stopped;
}

} // namespace slew::session

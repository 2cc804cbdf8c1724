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

// `done` wrapped so that whichever of several paths comes first calls it,
// and only once.
std::function<void()> once(std::function<void()> done)
{
    auto pending = std::make_shared<std::function<void()>>(std::move(done));
    return [pending] {
        if (!*pending)
            return;
        auto call = std::move(*pending);
        *pending = nullptr;
        call();
    };
}

} // namespace

void callWhenSent(RotatorSession &session, QObject *context, std::function<void()> done)
{
    // Lines held for a half-duplex line's turn-around are not on the link
    // yet: leaving now would lose them (a stop among them). Wait for them,
    // with the same limit.
    if (session.linesHeld()) {
        const auto finish = once(std::move(done));
        QObject::connect(
            &session, &RotatorSession::heldLinesWritten, context,
            [&session, context, finish] { callWhenSent(session, context, finish); }, Qt::SingleShotConnection);
        QTimer::singleShot(kFlushGiveUpMs, context, finish);
        return;
    }
    transport::Link *link = session.link();
    QIODevice *device = link ? link->device() : nullptr;
    if (!device || device->bytesToWrite() == 0) {
        QTimer::singleShot(0, context, std::move(done));
        return;
    }
    // Wait for the bytes to leave, from the event loop, with a limit.
    const auto finish = once(std::move(done));
    QObject::connect(device, &QIODevice::bytesWritten, context, [device, finish](qint64) {
        if (device->bytesToWrite() == 0)
            finish();
    });
    QTimer::singleShot(kFlushGiveUpMs, context, finish);
}

bool stopThenCall(RotatorSession &session, const QString &cause, QObject *context, std::function<void()> done)
{
    const bool stopped = session.link() && session.stop(cause);
    if (!session.stopHoldPending()) {
        callWhenSent(session, context, std::move(done));
        return stopped;
    }
    // The hold that brakes a free-running drive follows the stop in a
    // moment; leaving before it would let such a drive coast on. If the link
    // goes first, the hold never comes: give up after the flush limit.
    const auto finish = once(std::move(done));
    QObject::connect(
        &session, &RotatorSession::stopHoldSent, context,
        [&session, context, finish] { callWhenSent(session, context, finish); }, Qt::SingleShotConnection);
    QTimer::singleShot(kFlushGiveUpMs, context, finish);
    return stopped;
}

} // namespace slew::session

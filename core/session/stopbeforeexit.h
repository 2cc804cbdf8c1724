// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shutting down without leaving the antenna moving: stop the rotator, let
// the stop (and the hold that brakes a free-running drive) leave the link,
// then go. Used on SIGTERM / SIGINT by the station service, the operator
// window and slewctl alike.

#include <functional>

class QObject;

namespace slew::session {

class RotatorSession;

// Calls `done` (from the event loop, within `context`) once what the session
// has written has left the link, or after a second: a link that cannot take
// a few bytes in a second is gone anyway. Nothing here waits.
void callWhenSent(RotatorSession &session, QObject *context, std::function<void()> done);

// Sends a stop (for `cause`, as RotatorSession::stop) if there is a link,
// and calls `done` once the stop and its hold have been written out (as
// callWhenSent). Returns whether a stop was sent.
bool stopThenCall(RotatorSession &session, const QString &cause, QObject *context, std::function<void()> done);

} // namespace slew::session

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shutting down without leaving the antenna moving: stop the rotator, let
// the stop leave the link, then go. Used on SIGTERM / SIGINT by the station
// service and the operator window alike.

#include <functional>

class QObject;

namespace slew::session {

class RotatorSession;

// Sends a stop if there is a link, and calls `done` (from the event loop,
// within `context`) once it has been written out, or after a second: a link
// that cannot take a few bytes in a second is gone anyway. Returns whether a
// stop was sent. Nothing here waits.
bool stopThenCall(RotatorSession &session, QObject *context, std::function<void()> done);

} // namespace slew::session

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a helper of the session may do on the controller's link, and no
// more: the parts of the one conversation with a controller that live in
// classes of their own (controllerradiocommands.h: the radios' UP/DN;
// micro2gcalibration.h) write and ask through this narrow face of their
// RotatorSession, never through its insides. The session is the only
// implementation; a helper's requests go through the session's queue and
// are refused as the session's own are.

#include "requestqueue.h"
#include "sessiontypes.h"

#include "protocol/codec.h"
#include "protocol/message.h"

#include <QByteArray>
#include <QString>

#include <functional>

namespace slew::session {

class ControllerChannel {
public:
    // How the controller's commands are written, and what it can do.
    virtual const protocol::Codec &codec() const = 0;
    // Refused (and said, as the session's own refusals are) without a link.
    virtual CommandResult requireLink() = 0;
    // A refusal said as the session's own are (the result, and commandRefused()).
    virtual CommandResult refuse(const QString &reason) = 0;
    // A command with no answer, written at once.
    virtual void writeCommand(const QByteArray &line) = 0;
    // A query in the session's queue. Shared: one with the same line
    // already waiting serves this asker too, and nothing is added.
    enum class SameLine { Queued, Shared };
    virtual CommandResult queueRequest(Request request, SameLine same) = 0;
    // How many times the session retries a query that is not answered.
    virtual int retries() const = 0;
    // A failed query, said as the session says its own.
    virtual void reportRequestFailed(const QString &line, const QString &reason) = 0;
    // Reads the listing lines (Op::Calibration, Op::AdcReadings) that
    // arrive: says whether a line was one; one that is not (an echoed
    // command) completes no request.
    virtual void setListingReader(std::function<bool(const protocol::Message &)> reader) = 0;
    // The controller dropped its target (its scale changed under it).
    virtual void forgetActiveTarget() = 0;

protected:
    ~ControllerChannel() = default; // not owned through this face
};

} // namespace slew::session

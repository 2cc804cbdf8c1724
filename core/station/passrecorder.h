// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Keeps a record of every pass the station's pass runner tracks, however
// it was asked to (the service's --track, the window's Track, a schedule):
// at AOS it begins a record with the pass's times and the planner's
// predicted worst; while the pass is up it keeps a sample of where the
// antenna points and where the target is at most every kSampleSpacingMs of
// the pass's time, with the figures so far (the tracker's pointing error
// and commands, the radio's Doppler error); at LOS it finishes the record
// as tracked, and on anything that ends the pass sooner (Stop, untrack, a
// lost link, a changed clock, shutting down) as interrupted, saying why.
//
// The store (records/passrecordstore.h) commits what is gathered every two
// seconds, so a Slew killed mid-pass loses at most those; the next one to
// open the file marks the pass interrupted.

#include "records/passrecord.h"
#include "tracking/tracker.h"

#include <QObject>

#include <optional>

namespace slew::session {
class RotatorSession;
}
namespace slew::sky {
struct Pass;
}
namespace slew::tracking {
class PassRunner;
class StationClock;
struct TrackTarget;
}
namespace slew::records {
class PassRecordStore;
}

namespace slew::station {

class DopplerRadio;

class PassRecorder : public QObject {
    Q_OBJECT
public:
    // At most two samples a second of the pass: a picture needs no more,
    // and a day of passes stays a few megabytes.
    static constexpr int kSampleSpacingMs = 500;

    // All must outlive this; `radio` may be null (no Doppler figures).
    PassRecorder(session::RotatorSession *session, tracking::PassRunner *runner, DopplerRadio *radio,
                 const tracking::StationClock *clock, QObject *parent = nullptr);
    ~PassRecorder() override;

    // Where to record; nothing is recorded while it is null or not open to
    // record. A pass under way is finished in the store it began in.
    void setStore(records::PassRecordStore *store);
    records::PassRecordStore *store() const { return m_store; }

    // The record being written, while a pass is tracked.
    std::optional<qint64> currentRecord() const { return m_id; }

    // A pass that will not be tracked, and why: recorded as dropped. For a
    // schedule that has to leave one out. Its id, or nothing (no store, or
    // it could not be written: *error says why).
    std::optional<qint64> recordDropped(const tracking::TrackTarget &target, const sky::Pass &pass,
                                        const QString &reason, QString *error = nullptr);

    // What a record says of a pass before it is tracked.
    static records::PassPlanned planned(const tracking::TrackTarget &target, const sky::Pass &pass, bool rehearsal);

signals:
    // For the station service's log and the window's event log.
    void logLine(const QString &line);
    // A record was begun (running true) or finished.
    void recording(qint64 id, bool running);

private:
    void onTrackerState(tracking::Tracker::State state, const QString &why);
    void onPointingError(double degrees, double secondsFromAos);
    void begin();
    void finish(records::Outcome outcome, const QString &why);
    records::PassFigures figures() const;
    qint64 nowMs() const;
    QString rehearsalMark() const;

    session::RotatorSession *m_session;
    tracking::PassRunner *m_runner;
    DopplerRadio *m_radio;
    const tracking::StationClock *m_clock;
    records::PassRecordStore *m_store = nullptr;
    records::PassRecordStore *m_recordingIn = nullptr; // the store the current record began in
    std::optional<qint64> m_id;
    QString m_target;
    bool m_rehearsal = false; // the record under way is of a rehearsed pass
    qint64 m_lastSampleMs = 0;
    int m_samples = 0;
    bool m_radioSteered = false; // the radio tuned this pass: its figures are this pass's
};

} // namespace slew::station

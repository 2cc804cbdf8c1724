// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Station in this process as a face sees it (face/stationface.h): the
// operator at the station. Its state is read as the broker's is
// (stationstatereader.h, stationplanreader.h) and said as it changes (the
// plan, schedule and telemetry once per turn of the event loop however
// many parts changed in it); its intents go to the
// Station and its first rotor's session, through the same gate and the same
// rules as every other path to the wire, and are answered at once (but a
// schedule's preview, which is planned on a worker thread).
//
// The operator at the station stands above remote control: the holds that
// refuse a remote move (the operator's Stop, Slew's own tracking) do not
// refuse theirs; their Stop is what sets the hold.

#include "face/stationface.h"

#include <QTimer>

namespace slew::station {

class SchedulePreviewer;
class Station;
class StationStateReader;

class LocalStationFace : public face::StationFace {
    Q_OBJECT
public:
    explicit LocalStationFace(Station *station, QObject *parent = nullptr);
    ~LocalStationFace() override;

    QString title() const override;
    bool isLocal() const override { return true; }
    bool isLive() const override { return true; }
    QString whyNotLive() const override { return {}; }
    std::optional<face::StationState> state() const override;
    std::optional<face::StationPlan> plan() const override;
    std::optional<face::StationSchedule> schedule() const override;
    std::optional<qint64> stationClockMs() const override;
    model::MoveCheck previewPointing(double az, double el) const override;

    face::Outcome gotoPosition(double az, double el) override;
    face::Outcome stop(const QString &cause) override;
    face::Outcome park() override;
    face::Outcome home() override;
    face::Outcome track(const QString &target, double minElevationDeg) override;
    face::Outcome untrack() override;
    face::Outcome runSchedule(const QStringList &targets, const face::ScheduleRequest &request) override;
    face::Outcome stopSchedule() override;
    face::Outcome previewSchedule(const QStringList &targets, const face::ScheduleRequest &request) override;
    face::Outcome holdRadio(bool held) override;
    face::Outcome clearMotionFaults() override;
    face::Outcome startJog(double azSpeed, double elSpeed) override;
    void endJog(const QString &cause) override;

private:
    Station *m_station;
    StationStateReader *m_reader;
    SchedulePreviewer *m_previewer;
    int m_lastPreview = 0; // a preview's id is its number
    double m_jogAz = 0, m_jogEl = 0; // what a jog turns each axis at; 0: not
    // Changes that come in one turn of the event loop are said once.
    QTimer m_telemetryDue, m_planDue;
};

} // namespace slew::station

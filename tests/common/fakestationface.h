// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station's face whose state a test sets by hand (face/stationface.h),
// for a widget that shows a station: setState() says the new state as a
// station would. Its intents are refused, saying so, and counted.

#include "face/stationface.h"

class FakeStationFace : public slew::face::StationFace {
public:
    using Outcome = slew::face::Outcome;

    void setState(const slew::face::StationState &state)
    {
        m_state = state;
        emit stateChanged(state);
    }
    int intents = 0;

    QString title() const override { return QStringLiteral("fake"); }
    bool isLocal() const override { return true; }
    bool isLive() const override { return true; }
    QString whyNotLive() const override { return {}; }
    std::optional<slew::face::StationState> state() const override { return m_state; }
    std::optional<slew::face::StationPlan> plan() const override { return std::nullopt; }
    std::optional<slew::face::StationSchedule> schedule() const override { return std::nullopt; }
    std::optional<qint64> stationClockMs() const override { return std::nullopt; }
    slew::model::MoveCheck previewPointing(double, double) const override { return {QStringLiteral("a fake station")}; }
    Outcome gotoPosition(double, double) override { return refuse(); }
    Outcome stop(const QString &) override { return refuse(); }
    Outcome park() override { return refuse(); }
    Outcome home() override { return refuse(); }
    Outcome track(const QString &, double) override { return refuse(); }
    Outcome untrack() override { return refuse(); }
    Outcome runSchedule(const QStringList &, const slew::face::ScheduleRequest &) override { return refuse(); }
    Outcome stopSchedule() override { return refuse(); }
    Outcome previewSchedule(const QStringList &, const slew::face::ScheduleRequest &) override { return refuse(); }
    Outcome holdRadio(bool) override { return refuse(); }
    Outcome clearMotionFaults() override { return refuse(); }
    Outcome startJog(double, double) override { return refuse(); }
    void endJog(const QString &) override { ++intents; }

private:
    Outcome refuse()
    {
        ++intents;
        return Outcome::refused(QStringLiteral("a fake station does nothing"));
    }
    std::optional<slew::face::StationState> m_state;
};

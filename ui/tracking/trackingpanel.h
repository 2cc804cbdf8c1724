#pragma once
// The Tracking tab: the station and the element sets with their age, a
// target (a satellite found by name, the sun or the moon, favourites first:
// targetpicker.h), its passes in the next day with the
// plan each would get on this rotator (a badge for the overlap, the flip, an
// unwind or a lag), a countdown to AOS, Track and Stop tracking, and while
// it runs the target's place, range, range-rate and Doppler and the
// pointing error. The selected pass is drawn on the polar plot.

#include "rotor/passoverlay.h"

#include "sky/passes.h"
#include "sky/site.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QTimer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

class QLabel;
class QPushButton;
class QTableWidget;

namespace slew::session {
class RotatorSession;
}
namespace slew::sky {
class ElementSetSources;
}
namespace slew::station {
class Station;
}

namespace slew::ui {

class ElementSetAges;
class TargetPicker;

class TrackingPanel : public QWidget {
    Q_OBJECT
public:
    // Plans for the station's place by the station's clock, and tracks with
    // its pass runner; the station must outlive the panel. When the place or
    // the clock changes the passes are planned again (a running tracker
    // plans again by itself).
    explicit TrackingPanel(station::Station *station, QWidget *parent = nullptr);

    station::Station *station() const { return m_station; }

    // Selects the target whose name starts with `name` ("sun", "moon" too).
    bool selectTarget(const QString &name);
    QTableWidget *passTable() const { return m_passes; }
    QPushButton *trackButton() const { return m_track; }
    QPushButton *rehearseButton() const { return m_rehearse; }
    QPushButton *stopTrackingButton() const { return m_stopTracking; }
    QLabel *countdown() const { return m_countdown; }
    QLabel *live() const { return m_live; }
    tracking::PassRunner *runner() const { return m_runner; }
    TargetPicker *targetPicker() const { return m_picker; }
    ElementSetAges *elementSetAges() const { return m_setAges; }
    // The passes listed; empty while they are being planned (isPlanning).
    QList<sky::Pass> passes() const;
    bool isPlanning() const { return m_planning; }

signals:
    // The pass to draw on the plot, or none.
    void passOverlayChanged(std::optional<slew::ui::PassOverlay> overlay);
    void passTargetMoved(std::optional<QPointF> azEl);
    void message(const QString &text);
    // The pass table is filled (or emptied) for the target chosen.
    void passesShown();
    // The operator marked or unmarked a favourite.
    void favouritesChanged();
    // Rehearse this pass: the window starts the station clock two minutes
    // before this AOS.
    void rehearsePassRequested(double aosJulian);

private:
    void showStation();
    void showSetAges();
    void showPasses();
    void fillPasses(const QList<tracking::PlannedPass> &planned);
    void onPassChosen();
    void refreshLive();
    void startTracking();
    void showButtons(); // what Track and Stop tracking act on, and why one is greyed
    tracking::RotatorReach reach() const;
    std::optional<tracking::TrackTarget> chosenTarget() const;

    station::Station *m_station;
    session::RotatorSession *m_session;
    sky::ElementSetSources *m_sets;
    const tracking::StationClock *m_clock;
    tracking::PassRunner *m_runner;
    std::optional<tracking::TargetSky> m_sky; // the chosen target's, while there is a station
    QList<tracking::PlannedPass> m_planned; // the table's passes, sampled and planned
    bool m_planning = false;
    int m_generation = 0; // of the forecast wanted: one for an older choice is dropped

    QLabel *m_stationLine;
    ElementSetAges *m_setAges;
    TargetPicker *m_picker;
    QTableWidget *m_passes;
    QLabel *m_countdown;
    QLabel *m_live;
    QPushButton *m_track;
    QPushButton *m_rehearse;
    QPushButton *m_stopTracking;
    QTimer m_tick;
};

} // namespace slew::ui

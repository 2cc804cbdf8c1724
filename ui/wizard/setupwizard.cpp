// SPDX-License-Identifier: GPL-3.0-or-later
#include "setupwizard.h"

#include "calibrationpage.h"
#include "connectpage.h"
#include "homingpage.h"
#include "identifypage.h"
#include "mechanicspage.h"
#include "parkpage.h"
#include "summarypage.h"
#include "tuningpage.h"

#include "session/rotatorsession.h"

namespace slew::ui {

SetupWizard::SetupWizard(session::RotatorSession *session, QWidget *parent)
    : QWizard(parent), m_session(session), m_profile(session->profile())
{
    setWindowTitle(tr("Set up a rotator"));
    setOption(QWizard::NoBackButtonOnStartPage);
    setPage(ConnectPageId, new ConnectPage(this));
    setPage(IdentifyPageId, new IdentifyPage(this));
    setPage(MechanicsPageId, new MechanicsPage(this));
    setPage(HomingPageId, new HomingPage(this));
    setPage(TuningPageId, new TuningPage(this));
    setPage(ParkPageId, new ParkPage(this));
    setPage(SummaryPageId, new SummaryPage(this));
    setPage(CalibrationPageId, new CalibrationPage(this));
    // Big enough for the fullest page (tuning, with a chart and both sets of
    // figures, whose room the page keeps from the start) with some to spare,
    // so that no page scrolls at this size. Made smaller (a small screen),
    // each page scrolls (pagebody.h).
    resize(QSize(860, 720).expandedTo(minimumSizeHint()));
}

int SetupWizard::nextId() const
{
    // A controller that reads its rotor through a two-point calibration is
    // calibrated before the Mechanics page jogs it by its heading. The
    // other pages stay in order: Homing offers to skip a controller without
    // RESET, and tuning is optional.
    switch (currentId()) {
    case IdentifyPageId:
        return CalibrationPage::appliesTo(this) ? CalibrationPageId : MechanicsPageId;
    case CalibrationPageId:
        return MechanicsPageId;
    case SummaryPageId:
        return -1;
    default:
        return QWizard::nextId();
    }
}

void SetupWizard::reject()
{
    emit stopRequested();
    if (m_session->isConnected())
        m_session->stop();
    QWizard::reject();
}

} // namespace slew::ui

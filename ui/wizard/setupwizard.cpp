// SPDX-License-Identifier: GPL-3.0-or-later
#include "setupwizard.h"

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
    // Big enough for the fullest page (tuning, with a chart and both sets of
    // figures, whose room the page keeps from the start) with some to spare,
    // so that no page scrolls at this size. Made smaller (a small screen),
    // each page scrolls (pagebody.h).
    resize(QSize(860, 720).expandedTo(minimumSizeHint()));
}

void SetupWizard::reject()
{
    emit stopRequested();
    if (m_session->isConnected())
        m_session->stop();
    QWizard::reject();
}

} // namespace slew::ui

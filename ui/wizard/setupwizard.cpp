// SPDX-License-Identifier: GPL-3.0-or-later
#include "wizard/setupwizard.h"

#include "wizard/calibrationpage.h"
#include "wizard/connectpage.h"
#include "wizard/homingpage.h"
#include "wizard/identifypage.h"
#include "wizard/mechanicspage.h"
#include "wizard/parkpage.h"
#include "wizard/summarypage.h"
#include "wizard/tuningpage.h"

#include "stopbutton.h"

#include "session/rotatorsession.h"

#include <QKeyEvent>

namespace slew::ui {

SetupWizard::SetupWizard(session::RotatorSession *session, QWidget *parent)
    : QWizard(parent), m_session(session), m_profile(session->profile())
{
    setWindowTitle(tr("Set up a rotator"));
    setOption(QWizard::NoBackButtonOnStartPage);
    // The rotator the window talks to is the one set up, unless the operator
    // probes another link on the Connect page (which asks first).
    m_usesWindowConnection = windowHasConnection();
    if (m_usesWindowConnection)
        m_profile.uri = session->uri();
    // The STOP sits in the button row, outside the pages: it is there on
    // every page, however the page scrolls, and never behind anything.
    m_stop = new StopButton(session, this);
    m_stop->setObjectName(QStringLiteral("wizardStop"));
    m_stop->setToolTip(tr("Stop both axes now, and whatever the wizard is running (Esc)"));
    m_stop->setMinimumWidth(m_stop->sizeHint().width() * 2);
    connect(m_stop, &StopButton::stopped, this, &SetupWizard::stopRequested);
    setButton(QWizard::CustomButton1, m_stop);
    setOption(QWizard::HaveCustomButton1);
    setButtonLayout({QWizard::CustomButton1, QWizard::Stretch, QWizard::BackButton, QWizard::NextButton,
                     QWizard::CommitButton, QWizard::FinishButton, QWizard::CancelButton});
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

bool SetupWizard::windowHasConnection() const
{
    return m_session->state() != session::RotatorSession::State::Disconnected;
}

void SetupWizard::stopRotator()
{
    m_stop->stopFor(tr("the wizard's Stop")); // stopRequested() first, so no run sends a move after the stop
}

void SetupWizard::keyPressEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Escape && event->modifiers() == Qt::NoModifier) {
        stopRotator();
        event->accept();
        return;
    }
    QWizard::keyPressEvent(event);
}

void SetupWizard::reject()
{
    if (m_session->isConnected())
        stopRotator();
    else
        emit stopRequested(); // nothing to stop on the wire, but the probes end
    QWizard::reject();
}

} // namespace slew::ui

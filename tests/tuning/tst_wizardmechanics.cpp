// SPDX-License-Identifier: GPL-3.0-or-later
// The Mechanics page checks the direction of both axes: the azimuth's jog
// and the elevation's, each confirmed by the operator before Next. An
// elevation whose motor is wired the wrong way round (the simulator's
// `reversed=el`) runs away from its jog: the page sees the reading go the
// wrong way, stops the rotator and will not let it be confirmed.
#include "../common/simulatorpump.h"

#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulatorscheme.h"
#include "wizard/setupwizard.h"

#include <QCheckBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace slew;
using session::RotatorSession;
using ui::SetupWizard;

class WizardMechanicsTest : public QObject {
    Q_OBJECT

    std::unique_ptr<RotatorSession> m_session;
    std::unique_ptr<SimulatorPump> m_pump;

    template<typename T>
    static T *find(SetupWizard &w, const char *name)
    {
        T *child = w.currentPage()->findChild<T *>(QLatin1String(name));
        if (!child)
            qWarning() << "no" << name << "on page" << w.currentId();
        return child;
    }
    static bool canGoOn(SetupWizard &w) { return w.button(QWizard::NextButton)->isEnabled(); }

    // The wizard at the Mechanics page, the azimuth jogged and confirmed.
    void azimuthChecked(SetupWizard &wizard)
    {
        wizard.setStartId(SetupWizard::MechanicsPageId);
        wizard.show();
        QCOMPARE(wizard.currentId(), int(SetupWizard::MechanicsPageId));
        QTest::mouseClick(find<QPushButton>(wizard, "jog"), Qt::LeftButton);
        TRY_VERIFY(std::fabs(m_session->azimuth() - 17.0) < 0.2);
        auto *confirmed = find<QCheckBox>(wizard, "jogConfirmed");
        QVERIFY(confirmed->isEnabled());
        confirmed->setChecked(true);
    }

private slots:
    void initTestCase() { registerLinkSchemes(); }

    void cleanup()
    {
        m_pump.reset();
        m_session.reset();
    }

    void bothAxesMustBeConfirmed()
    {
        QVERIFY(connectPumped(QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=12&start_el=6"), m_session,
                              m_pump));
        SetupWizard wizard(m_session.get());
        azimuthChecked(wizard);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(!canGoOn(wizard)); // the elevation is not checked yet

        auto *jogElevation = find<QPushButton>(wizard, "jogElevation");
        QVERIFY(jogElevation && jogElevation->isVisible());
        QTest::mouseClick(jogElevation, Qt::LeftButton);
        TRY_VERIFY(std::fabs(m_session->elevation() - 11.0) < 0.2);
        QVERIFY(find<QLabel>(wizard, "elDirection")->text().contains(QStringLiteral("as sent")));
        auto *confirmed = find<QCheckBox>(wizard, "jogElevationConfirmed");
        QVERIFY(confirmed->isEnabled());
        QVERIFY(confirmed->text().contains(QStringLiteral("up")));
        QVERIFY(!canGoOn(wizard));
        confirmed->setChecked(true);
        QVERIFY(canGoOn(wizard));
    }

    void aReversedElevationIsStoppedAndCannotBeConfirmed()
    {
        QVERIFY(connectPumped(QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=12&start_el=30&reversed=el"),
                              m_session, m_pump));
        SetupWizard wizard(m_session.get());
        azimuthChecked(wizard);
        if (QTest::currentTestFailed())
            return;

        QSignalSpy stops(m_session.get(), &RotatorSession::stopSent);
        auto *jogElevation = find<QPushButton>(wizard, "jogElevation");
        QVERIFY(jogElevation);
        QTest::mouseClick(jogElevation, Qt::LeftButton);
        auto *note = find<QLabel>(wizard, "elDirection");
        TRY_VERIFY(note->text().contains(QStringLiteral("wrong way")));
        QCOMPARE(stops.count(), 1);

        // Stopped at the wrong-way mark (a degree below where it started),
        // and it stays there.
        sim::Simulator *sim = sim::simulatorBehind(m_session->link());
        const sim::AxisModel &elevation = sim->rotator().axis(sim::Axis::Elevation);
        TRY_VERIFY(elevation.isStopped() && elevation.velocity() == 0.0);
        const double stoppedAt = elevation.position();
        QVERIFY2(stoppedAt < 29.05 && stoppedAt > 28.0, qPrintable(QString::number(stoppedAt)));
        const double until = sim->clock().now() + 3.0;
        TRY_VERIFY(sim->clock().now() > until);
        QCOMPARE(elevation.position(), stoppedAt);

        auto *confirmed = find<QCheckBox>(wizard, "jogElevationConfirmed");
        QVERIFY(!confirmed->isEnabled());
        QVERIFY(!confirmed->isChecked());
        QVERIFY(!canGoOn(wizard));
    }
};

QTEST_MAIN(WizardMechanicsTest)
#include "tst_wizardmechanics.moc"

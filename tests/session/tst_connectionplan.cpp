// SPDX-License-Identifier: GPL-3.0-or-later
// What connecting to a URI means for the rotator profile, as every face and
// program asks it of session/connectionplan.h: the window's list against a
// URI that names its dialect, a program's --dialect against the same, a
// rotctld:// peer, a firmware that cannot speak the dialect, the travel a
// simulator's URI names, and the calibration remembered per rotator.

#include "linkschemes.h"
#include "model/savedcalibration.h"
#include "session/connectionplan.h"

#include <QCoreApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

using slew::model::RotatorProfile;
using slew::protocol::Dialect;
using slew::protocol::Firmware;
using namespace slew::session;

class ConnectionPlanTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        slew::registerLinkSchemes(); // sim: and rotctld:// say what they are
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("SlewTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_connectionplan"));
    }
    void init() { QSettings().remove(QStringLiteral("calibration")); }
    void cleanup() { QSettings().remove(QStringLiteral("calibration")); }

    void theWindowShowsWhatTheLinkNames()
    {
        RotatorProfile mine;
        mine.name = QStringLiteral("mine");
        const RotatorProfile p =
            windowConnectionProfile(QStringLiteral("sim:?dialect=gs232b&az_max=450&el_max=180&park_az=90"), mine,
                                    Dialect::Easycomm3, {});
        QCOMPARE(p.uri, QStringLiteral("sim:?dialect=gs232b&az_max=450&el_max=180&park_az=90"));
        QCOMPARE(p.name, QStringLiteral("mine"));
        QCOMPARE(p.dialect, Dialect::Gs232B); // the link's word over the list's
        QCOMPARE(p.limits.azMax, 450.0);
        QCOMPARE(p.limits.elMax, 180.0);
        QCOMPARE(p.parkAz, 90.0);
        // A rotctld:// peer speaks rotctld, whatever the list says.
        QCOMPARE(windowConnectionProfile(QStringLiteral("rotctld://127.0.0.1:4533"), mine, Dialect::Gs232A, {}).dialect,
                 Dialect::Rotctld);
    }

    void theWindowKeepsItsChoiceForHardware()
    {
        RotatorProfile mine;
        mine.limits.azMax = 360.0;
        mine.firmware = Firmware::SatNogs;
        // A serial port says nothing of its far end: the list's dialect and
        // the profile's travel stand; SatNOGS's ways never ride GS-232.
        const RotatorProfile p = windowConnectionProfile(QStringLiteral("serial:/dev/ttyUSB0"), mine, Dialect::Gs232B, {});
        QCOMPARE(p.dialect, Dialect::Gs232B);
        QCOMPARE(p.limits.azMax, 360.0);
        QCOMPARE(p.firmware, Firmware::Generic);
        // A firmware the URI names, where it speaks the dialect chosen.
        QCOMPARE(windowConnectionProfile(QStringLiteral("serial:/dev/ttyUSB0?firmware=k3ng"), mine, Dialect::Gs232B, {})
                     .firmware,
                 Firmware::K3ng);
    }

    void theWindowPutsBackEachRotatorsCalibration()
    {
        RotatorProfile mine;
        mine.azOffsetDeg = 1.5;
        mine.elOffsetDeg = -0.5;
        const QString here = QStringLiteral("tcp://10.0.0.5:4001"), there = QStringLiteral("tcp://10.0.0.6:4001");
        // The same rotator again, nothing saved: its offsets stay.
        RotatorProfile p = windowConnectionProfile(here, mine, Dialect::Easycomm2, here);
        QCOMPARE(p.azOffsetDeg, 1.5);
        // Another rotator does not inherit them...
        p = windowConnectionProfile(there, mine, Dialect::Easycomm2, here);
        QCOMPARE(p.azOffsetDeg, 0.0);
        QCOMPARE(p.elOffsetDeg, 0.0);
        // ...and gets its own, where they were found before.
        slew::model::saveCalibration(there, {2.25, 0.75});
        p = windowConnectionProfile(there, mine, Dialect::Easycomm2, here);
        QCOMPARE(p.azOffsetDeg, 2.25);
        QCOMPARE(p.elOffsetDeg, 0.75);
    }

    void aProgramTakesTheOperatorsDialect()
    {
        RotatorProfile p;
        p.dialect = Dialect::Easycomm2;
        p.uri = QStringLiteral("sim:?dialect=gs232b&az_max=450");
        QCOMPARE(commandLineConnectionProfile(p, true).dialect, Dialect::Easycomm2); // --dialect said so
        QCOMPARE(commandLineConnectionProfile(p, false).dialect, Dialect::Gs232B);   // the URI's, unasked
        // A program's travel is its --limits, not the URI's.
        QCOMPARE(commandLineConnectionProfile(p, false).limits.azMax, p.limits.azMax);
        p.uri = QStringLiteral("rotctld://127.0.0.1:4533");
        QCOMPARE(commandLineConnectionProfile(p, true).dialect, Dialect::Rotctld);
    }

    void aProbeAsksInTheLinksDialect()
    {
        QCOMPARE(probeDialect(QStringLiteral("sim:?dialect=micro2g"), Dialect::Easycomm2), Dialect::Micro2g);
        QCOMPARE(probeDialect(QStringLiteral("serial:/dev/ttyUSB0"), Dialect::Gs232A), Dialect::Gs232A);
        QCOMPARE(probeDialect(QStringLiteral("sim:?dialect=nonsense"), Dialect::Gs232A), Dialect::Gs232A);
    }
};

QTEST_GUILESS_MAIN(ConnectionPlanTest)
#include "tst_connectionplan.moc"

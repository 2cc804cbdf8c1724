// SPDX-License-Identifier: GPL-3.0-or-later
// The window's lines that say what is going on clear or change when it ends,
// and the Events log has each operator action and how it ended, once:
// - a preset's "Going to" after arrival and after Stop; the target readout
//   after Stop;
// - the plot's "Going to az…" back to its prompt on arrival;
// - "Parking at…" after the park;
// - "Reading N registers…" once the last has answered;
// - a failed connection logged once, and its cause kept in view;
// - a file dialog (Export CSV…) that leaves Stop within reach.

#include "windowfixture.h"

#include "eventlog.h"
#include "rotor/configeditor.h"
#include "rotor/jogpad.h"
#include "rotor/parkhomepanel.h"
#include "rotor/presetpanel.h"
#include "rotor/targetconfirmation.h"
#include "stopbutton.h"

#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

namespace {

int linesWith(const WindowFixture &f, const QString &text)
{
    int n = 0;
    for (const QString &line : f.window->eventLog()->toPlainText().split(QLatin1Char('\n')))
        n += line.contains(text) ? 1 : 0;
    return n;
}

QString textOf(const WindowFixture &f, const char *name)
{
    auto *label = f.find<QLabel>(QLatin1String(name));
    return label ? label->text() : QStringLiteral("(no %1)").arg(QLatin1String(name));
}

// A preset "Mast" at az 40, el 20, and the rotator back at az 0, el 10.
bool prepareMastPreset(WindowFixture &f)
{
    return f.session.gotoPosition(40, 20) && f.waitUntilAt(40, 20, 0.3)
           && f.window->presetPanel()->storeCurrent(QStringLiteral("Mast")) && f.session.gotoPosition(0, 10)
           && f.waitUntilAt(0, 10, 0.3) && f.waitUntilStill();
}

} // namespace

class StatusLinesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void aPresetsLineClearsOnArrivalAndTheLogSaysSoOnce()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(prepareMastPreset(f));
        QVERIFY(f.window->presetPanel()->recall(0));
        QCOMPARE(textOf(f, "presetMessage"), QStringLiteral("Going to 'Mast'."));
        QVERIFY2(f.waitFor([&] { return textOf(f, "presetMessage").isEmpty(); }, 20000),
                 qPrintable(textOf(f, "presetMessage")));
        QVERIFY(f.waitUntilAt(40, 20, 1.0));
        const QString move = QStringLiteral("preset 'Mast' (az 40.0°, el ");
        QVERIFY2(linesWith(f, move) == 2, qPrintable(f.window->eventLog()->toPlainText())); // sent, and how it ended
        QCOMPARE(linesWith(f, QStringLiteral("°): arrived, at az ")), 1);
    }

    void stopEndsTheLinesAndTheTarget()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(prepareMastPreset(f));
        QVERIFY(f.window->presetPanel()->recall(0));
        QVERIFY(!textOf(f, "readoutTarget").isEmpty());
        QVERIFY(f.waitFor([&] { return f.session.azimuth() > 10; }, 20000));
        f.window->stopButton()->click();
        QCOMPARE(textOf(f, "presetMessage"), QString());
        QCOMPARE(textOf(f, "readoutTarget"), QString());
        QCOMPARE(linesWith(f, QStringLiteral("Stop")), 1);
        QCOMPARE(linesWith(f, QStringLiteral("Stop (the STOP button) at az ")), 1); // what asked, and where
        QVERIFY2(linesWith(f, QStringLiteral("°): stopped at az ")) == 1, qPrintable(f.window->eventLog()->toPlainText()));
        // Coming to rest afterwards is not another ending.
        QVERIFY(f.waitUntilStill());
        QCOMPARE(linesWith(f, QStringLiteral("preset 'Mast'")), 2);
    }

    void aJogsReleaseIsAStopThatSaysSo()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->jogPad()->press(slew::ui::JogPad::Right);
        QVERIFY(f.waitFor([&] { return f.session.azimuth() > 2; }, 20000));
        f.window->jogPad()->release(slew::ui::JogPad::Right);
        QCOMPARE(linesWith(f, QStringLiteral("jog azimuth clockwise at ")), 1);
        QCOMPARE(linesWith(f, QStringLiteral("Stop (jog azimuth clockwise released) at az ")), 1);
    }

    void thePlotsLineGoesBackToItsPromptOnArrival()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        auto *question = f.find<QLabel>(QStringLiteral("targetQuestion"));
        const QString prompt = question->text();
        f.window->targetConfirmation()->ask(30, 15);
        f.window->targetConfirmation()->accept();
        QCOMPARE(question->text(), QStringLiteral("Going to az 30.0°, el 15.0°."));
        QVERIFY2(f.waitFor([&] { return question->text() == prompt; }, 20000), qPrintable(question->text()));
        QCOMPARE(linesWith(f, QStringLiteral("go to az 30.0°, el 15.0° (picked on the plot): arrived")), 1);
    }

    void theParkLineClearsWhenParked()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.waitFor([&] { return f.session.parkKnown(); }, 10000));
        QVERIFY(f.session.gotoPosition(60, 30) && f.waitUntilAt(60, 30, 0.5));
        QVERIFY(f.window->parkHomePanel()->park());
        QVERIFY(textOf(f, "homeMessage").startsWith(QStringLiteral("Parking at")));
        QVERIFY2(f.waitFor([&] { return textOf(f, "homeMessage").isEmpty(); }, 20000),
                 qPrintable(textOf(f, "homeMessage")));
        QVERIFY(f.waitFor([&] { return linesWith(f, QStringLiteral(": arrived, at ")) == 1; }, 1000));
        QCOMPARE(linesWith(f, QStringLiteral("park (")), 2);
    }

    void readingTheRegistersEnds()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->configEditor()->readAll();
        QVERIFY(textOf(f, "configMessage").startsWith(QStringLiteral("Reading ")));
        QVERIFY2(f.waitFor([&] { return textOf(f, "configMessage").startsWith(QStringLiteral("Read ")); }, 20000),
                 qPrintable(textOf(f, "configMessage")));
        QVERIFY2(textOf(f, "configMessage").contains(QStringLiteral("registers.")), qPrintable(textOf(f, "configMessage")));
    }

    void fileDialogsLeaveStopWithinReach()
    {
        // Export CSV…: the file dialog is up, and nothing is modal, so the
        // window's Stop can still be clicked; choosing a file exports.
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.find<QPushButton>(QStringLiteral("chartExport"))->click();
        auto *dialog = f.window->findChild<QFileDialog *>(QStringLiteral("fileChooser"));
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QCOMPARE(QApplication::activeModalWidget(), nullptr);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("telemetry.csv"));
        dialog->selectFile(path);
        static_cast<QDialog *>(dialog)->accept(); // as its Save button does
        QVERIFY(QFileInfo::exists(path));
    }

    void aFailedConnectionIsLoggedOnceAndItsCauseStays()
    {
        WindowFixture f(QStringLiteral("serial:/dev/ttySLEWNOPE"));
        f.window->connectTo(f.uri);
        QVERIFY(f.waitFor([&] { return linesWith(f, QStringLiteral("cannot open")) > 0; }, 10000));
        // The error held for a turn of the event loop has had its turn.
        for (int i = 0; i < 5; ++i)
            QCoreApplication::processEvents();
        QCOMPARE(linesWith(f, QStringLiteral("cannot open")), 1);
        QVERIFY2(textOf(f, "linkProblem").contains(QStringLiteral("cannot open")), qPrintable(textOf(f, "linkProblem")));
    }
};

QTEST_MAIN(StatusLinesTest)
#include "tst_statuslines.moc"

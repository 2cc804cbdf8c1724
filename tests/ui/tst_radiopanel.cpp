// SPDX-License-Identifier: GPL-3.0-or-later
// The Radio tab in the operator window, on a real X11 server: a radio URI
// the station refuses is said and changes nothing; frequencies are read as
// the station service reads them, a bad one refused under its field with no
// plan set, good ones set the station radio's plan; what is applied is kept
// per satellite and comes back when that satellite is tracked again, and at
// the next start with the radio's link. With Hamlib's own rigctld (dummy
// rig) as the radio, the panel connects and says so, says the tries after
// the radio is lost, and through a rehearsed pass of FLOCK 2P-1 over JO65hq
// (2018-01-22, AOS 09:15:45 above 0°, on the built-in rotator simulator at
// 20 times) shows what the radio is sent, the Doppler shift and the pass's
// figures, which stay after LOS, while the Telemetry tab charts the Doppler
// error. The tab holds at 1280x720 with every line filled.

#include "../common/hamlibprocess.h"
#include "layoutfaults.h"
#include "windowfixture.h"

#include "linkschemes.h"
#include "operatortheme.h"
#include "radio/radiolinkbox.h"
#include "radio/radiopanel.h"
#include "radio/radioplanform.h"
#include "radio/radiotransponderdialog.h"
#include "radio/transpondersources.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"
#include "radio/dopplersteering.h"
#include "station/dopplerradio.h"
#include "telemetry/telemetrycharts.h"
#include "telemetry/telemetryrecorder.h"
#include "tracking/trackingpanel.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QFile>
#include <QTabWidget>
#include <QTest>
#include <QWheelEvent>
#include <QXYSeries>

using slew::radio::DopplerOn;
using slew::radio::RadioPlan;
using slew::radio::UplinkFollowsDial;
using slew::station::DopplerRadio;
using slew::ui::RadioPanel;
using slew::ui::TelemetryRecorder;
using slew::ui::TrackingPanel;

namespace {

const QString kAllSets = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");
constexpr int kFlock = 41617;
constexpr int kJpss = 43013;

// Tracks `name` from the Tracking tab, as the operator does.
bool track(WindowFixture &f, const QString &name)
{
    TrackingPanel *tracking = f.window->trackingPanel();
    if (!tracking->selectTarget(name))
        return false;
    QTest::mouseClick(tracking->trackButton(), Qt::LeftButton);
    return tracking->runner()->isRunning();
}

// Once the pass is planned and waited for: the Tracking tab's Track comes
// back with the tracker's state.
void untrack(WindowFixture &f)
{
    const slew::tracking::Tracker &tracker = f.window->trackingPanel()->runner()->tracker();
    if (!QTest::qWaitFor([&] { return tracker.state() != slew::tracking::Tracker::State::Idle; }, 10000))
        qWarning("the pass was never planned");
    QTest::mouseClick(f.window->trackingPanel()->stopTrackingButton(), Qt::LeftButton);
}

// The Radio tab brought to the front, as the operator would to type in it.
RadioPanel *radioTab(WindowFixture &f)
{
    RadioPanel *panel = f.window->radioPanel();
    f.window->bringToFront(panel);
    // Typed digits reach a field only while it has the focus (the window
    // takes 1 to 9 for the presets otherwise): the window must be active.
    f.window->activateWindow();
    if (!QTest::qWaitForWindowActive(f.window.get()))
        qWarning("the window did not become active");
    return panel;
}

template <typename T>
T *in(RadioPanel *panel, const char *name)
{
    T *found = panel->findChild<T *>(QString::fromLatin1(name));
    if (!found)
        qWarning("no %s in the Radio tab", name);
    return found;
}

QString textOf(RadioPanel *panel, const char *name)
{
    const QLabel *label = in<QLabel>(panel, name);
    return label ? label->text() : QString();
}

// Types into a frequency or offset field, or a mode's editable list.
void type(RadioPanel *panel, const char *name, const QString &text)
{
    QWidget *w = in<QWidget>(panel, name);
    if (auto *combo = qobject_cast<QComboBox *>(w))
        WindowFixture::typeInto(combo->lineEdit(), text);
    else if (auto *field = qobject_cast<QLineEdit *>(w))
        WindowFixture::typeInto(field, text);
}

void choose(RadioPanel *panel, const char *name, const QString &word)
{
    auto *combo = in<QComboBox>(panel, name);
    combo->setCurrentIndex(combo->findData(word));
}

void apply(RadioPanel *panel)
{
    QTest::mouseClick(in<QPushButton>(panel, "radioApply"), Qt::LeftButton);
}

void connectRadio(RadioPanel *panel, const QString &uri)
{
    type(panel, "radioUri", uri);
    QTest::mouseClick(in<QPushButton>(panel, "radioConnect"), Qt::LeftButton);
}

// An error label shown under its field, saying `words`.
bool refusedWith(RadioPanel *panel, const char *name, const QString &words)
{
    const QLabel *label = in<QLabel>(panel, name);
    if (label && !(label->isVisible() && label->text().contains(words)))
        qWarning("%s: '%s'%s", name, qPrintable(label->text()), label->isVisible() ? "" : " (not shown)");
    return label && label->isVisible() && label->text().contains(words);
}

// FLOCK 2P-1's transponder as an operator writes it: 70 cm down in USB, 2 m up
// in LSB (an inverting linear transponder), with its calibration.
void typeLinearTransponder(RadioPanel *panel)
{
    type(panel, "radioDownlink", QStringLiteral("435.85M"));
    type(panel, "radioUplink", QStringLiteral("145.95 MHz"));
    type(panel, "radioReceiveMode", QStringLiteral("usb"));
    type(panel, "radioTransmitMode", QStringLiteral("LSB"));
    type(panel, "radioDownlinkOffset", QStringLiteral("-1.2k"));
    type(panel, "radioUplinkOffset", QStringLiteral("350"));
    choose(panel, "radioDoppler", QStringLiteral("both"));
    choose(panel, "radioUplinkFollows", QStringLiteral("opposite"));
}

} // namespace

class RadioPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QCOMPARE(QGuiApplication::platformName(), QStringLiteral("xcb"));
        QVERIFY2(!hamlibProgram("rigctld").isEmpty(), "rigctld is not installed: packaging/dev.sh installs libhamlib-utils");
        WindowFixture::prepareApplication();
        slew::registerLinkSchemes();
        slew::ui::applyOperatorTheme(*qobject_cast<QApplication *>(QCoreApplication::instance()));
    }

    // Each test starts with no radio kept: the last one's would connect.
    void init() { QSettings().remove(QStringLiteral("radio")); }

    void aRefusedUriIsSaidAndChangesNothing()
    {
        WindowFixture f;
        RadioPanel *panel = radioTab(f);
        DopplerRadio *radio = f.station.radio();
        const QStringList offered = panel->linkBox()->offeredUris();
        QVERIFY2(offered.contains(QStringLiteral("sim:")) && offered.contains(QStringLiteral("rigctld://127.0.0.1:4532"))
                     && offered.contains(QStringLiteral("controller")),
                 qPrintable(offered.join(u' ')));

        connectRadio(panel, QStringLiteral("nosuch://x"));
        QVERIFY(refusedWith(panel, "radioLinkRefusal", QStringLiteral("nosuch://x: unknown radio link kind 'nosuch'")));
        QCOMPARE(radio->linkUri(), QString());
        QVERIFY(!radio->isWanted());
        QVERIFY(!QSettings().contains(QStringLiteral("radio/uri")));
        QVERIFY(!panel->linkBox()->offeredUris().contains(QStringLiteral("nosuch://x")));

        // A radio held is kept through a refusal: here one that never answers.
        const quint16 nobody = freeTcpPort();
        const QString held = QStringLiteral("rigctld://127.0.0.1:%1").arg(nobody);
        connectRadio(panel, held);
        QVERIFY(!in<QLabel>(panel, "radioLinkRefusal")->isVisible());
        QCOMPARE(radio->linkUri(), held);
        QVERIFY(radio->isWanted());
        // (Not a prefix of a URI offered, which the list would complete.)
        connectRadio(panel, QStringLiteral("rigctld://:4532"));
        QVERIFY(refusedWith(panel, "radioLinkRefusal", QStringLiteral("no host named")));
        QCOMPARE(radio->linkUri(), held);
        QVERIFY(radio->isWanted());
        QCOMPARE(QSettings().value(QStringLiteral("radio/uri")).toString(), held);
        QTest::mouseClick(in<QPushButton>(panel, "radioDisconnect"), Qt::LeftButton);
        QVERIFY(!radio->isWanted());
    }

    void vfosAndPuttingBackAreTheRadiosAndKept()
    {
        {
            WindowFixture f;
            RadioPanel *panel = radioTab(f);
            DopplerRadio *radio = f.station.radio();
            QCOMPARE(radio->vfoLayout(), slew::radio::VfoLayout::Split);
            QVERIFY(!radio->restoresAfterPass());
            choose(panel, "radioVfos", QStringLiteral("main-sub"));
            QCOMPARE(radio->vfoLayout(), slew::radio::VfoLayout::MainSub);
            QTest::mouseClick(in<QCheckBox>(panel, "radioRestore"), Qt::LeftButton);
            QVERIFY(radio->restoresAfterPass());
            // The controller's UP/DN has no Main and Sub: refused as a radio
            // while satellite mode is chosen...
            connectRadio(panel, QStringLiteral("controller"));
            QVERIFY(refusedWith(panel, "radioLinkRefusal", QStringLiteral("no Main and Sub VFOs")));
            QCOMPARE(radio->linkUri(), QString());
            // ...and satellite mode refused while it is the radio.
            choose(panel, "radioVfos", QStringLiteral("split"));
            connectRadio(panel, QStringLiteral("controller"));
            QCOMPARE(radio->linkUri(), QStringLiteral("controller"));
            choose(panel, "radioVfos", QStringLiteral("main-sub"));
            QVERIFY(refusedWith(panel, "radioVfoRefusal", QStringLiteral("controller has no Main and Sub VFOs to "
                                                                          "address; the radio keeps split")));
            QCOMPARE(radio->vfoLayout(), slew::radio::VfoLayout::Split);
            choose(panel, "radioVfos", QStringLiteral("split"));
            QVERIFY(!in<QLabel>(panel, "radioVfoRefusal")->isVisible());
            choose(panel, "radioVfos", QStringLiteral("main-sub"));
            QTest::mouseClick(in<QPushButton>(panel, "radioDisconnect"), Qt::LeftButton);
        }
        // Both are kept for the next start.
        QSettings().remove(QStringLiteral("radio/uri"));
        WindowFixture f;
        RadioPanel *panel = radioTab(f);
        QCOMPARE(f.station.radio()->vfoLayout(), slew::radio::VfoLayout::MainSub);
        QVERIFY(f.station.radio()->restoresAfterPass());
        QVERIFY(in<QCheckBox>(panel, "radioRestore")->isChecked());
    }

    void badFrequenciesAreRefusedUnderTheirFields()
    {
        WindowFixture f;
        f.window->resize(1280, 720);
        RadioPanel *panel = radioTab(f);
        DopplerRadio *radio = f.station.radio();

        // Megahertz without the unit, NaN, a mode with a passband in it, a
        // calibration of megahertz, and a field left empty.
        type(panel, "radioDownlink", QStringLiteral("145.8"));
        type(panel, "radioUplink", QStringLiteral("nan"));
        type(panel, "radioReceiveMode", QStringLiteral("USB 2400"));
        type(panel, "radioDownlinkOffset", QStringLiteral("2M"));
        apply(panel);
        // Every refusal at once still fits the smallest screen, whole.
        type(panel, "radioTransmitMode", QStringLiteral("SSB/CW"));
        type(panel, "radioUplinkOffset", QStringLiteral("lots"));
        apply(panel);
        QCoreApplication::processEvents();
        const QString faults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
        QVERIFY2(faults.isEmpty(), qPrintable(faults));
        QCOMPARE(f.window->size(), QSize(1280, 720));
        QVERIFY(refusedWith(panel, "radioTransmitModeError", QStringLiteral("'SSB/CW' is not a Hamlib mode")));
        QVERIFY(refusedWith(panel, "radioUplinkOffsetError", QStringLiteral("'lots' is not a frequency")));
        type(panel, "radioTransmitMode", QString());
        type(panel, "radioUplinkOffset", QString());
        apply(panel);
        QVERIFY(refusedWith(panel, "radioDownlinkError", QStringLiteral("145.8 Hz is below 1 MHz")));
        QVERIFY(refusedWith(panel, "radioUplinkError", QStringLiteral("'nan' is not a frequency")));
        QVERIFY(refusedWith(panel, "radioReceiveModeError", QStringLiteral("'USB 2400' is not a Hamlib mode name")));
        QVERIFY(refusedWith(panel, "radioDownlinkOffsetError", QStringLiteral("Downlink calibration")));
        QVERIFY(!in<QLabel>(panel, "radioUplinkOffsetError")->isVisible());
        QVERIFY(textOf(panel, "radioPlanState").startsWith(QStringLiteral("Not applied")));
        QVERIFY(!radio->plan());
        QVERIFY(!QSettings().contains(QStringLiteral("radio/lastPlan")));

        type(panel, "radioDownlink", QString());
        type(panel, "radioUplink", QString());
        type(panel, "radioReceiveMode", QString());
        type(panel, "radioDownlinkOffset", QString());
        apply(panel);
        QVERIFY(refusedWith(panel, "radioDownlinkError", QStringLiteral("is needed")));
        QVERIFY(!radio->plan());

        // Right one by one, wrong only together: Doppler on an uplink there is not.
        type(panel, "radioDownlink", QStringLiteral("437.8M"));
        choose(panel, "radioDoppler", QStringLiteral("uplink"));
        apply(panel);
        QVERIFY(!in<QLabel>(panel, "radioDownlinkError")->isVisible());
        QVERIFY(refusedWith(panel, "radioDopplerError", QStringLiteral("no uplink")));
        QVERIFY(!radio->plan());
        // No number the panel shows is NaN.
        for (const QLabel *label : panel->findChildren<QLabel *>())
            QVERIFY2(!label->text().contains(QStringLiteral("nan"), Qt::CaseSensitive)
                         || label->objectName() == QLatin1String("radioUplinkError"),
                     qPrintable(label->objectName() + QStringLiteral(": ") + label->text()));
    }

    void goodFrequenciesSetTheRadiosPlan()
    {
        WindowFixture f;
        RadioPanel *panel = radioTab(f);
        DopplerRadio *radio = f.station.radio();
        typeLinearTransponder(panel);
        apply(panel);
        QVERIFY2(!panel->planForm()->showsRefusal(), qPrintable(textOf(panel, "radioPlanState")));
        QVERIFY(radio->plan());
        const RadioPlan &plan = *radio->plan();
        QCOMPARE(plan.frequencies.downlinkHz, 435.85e6);
        QVERIFY(plan.frequencies.uplinkHz);
        QCOMPARE(*plan.frequencies.uplinkHz, 145.95e6);
        QCOMPARE(plan.frequencies.downlinkOffsetHz, -1200.0);
        QCOMPARE(plan.frequencies.uplinkOffsetHz, 350.0);
        QCOMPARE(plan.frequencies.correct, DopplerOn::Both);
        QCOMPARE(plan.frequencies.uplinkFollows, UplinkFollowsDial::OppositeWay);
        QCOMPARE(plan.receiveMode, QStringLiteral("USB"));
        QCOMPARE(plan.transmitMode, QStringLiteral("LSB"));
        QCOMPARE(plan.noradId, 0); // nothing tracked: for whatever is
        QCOMPARE(textOf(panel, "radioPlanState"),
                 QStringLiteral("Applied for any satellite tracked: downlink 435.848 800 MHz USB, uplink 145.950 350 MHz LSB."));
        QCOMPARE(textOf(panel, "radioNominal"),
                 QStringLiteral("down 435.850 000 MHz (calibration −1 200 Hz), up 145.950 000 MHz (calibration +350 Hz)"));

        // Downlink only, receive only, the dial followed by nothing.
        type(panel, "radioUplink", QString());
        type(panel, "radioTransmitMode", QString());
        type(panel, "radioDownlinkOffset", QString());
        choose(panel, "radioDoppler", QStringLiteral("downlink"));
        choose(panel, "radioUplinkFollows", QStringLiteral("no"));
        apply(panel);
        QVERIFY(radio->plan());
        QVERIFY(!radio->plan()->frequencies.uplinkHz);
        QCOMPARE(radio->plan()->frequencies.downlinkOffsetHz, 0.0);
        QCOMPARE(radio->plan()->frequencies.correct, DopplerOn::DownlinkOnly);
        QCOMPARE(radio->plan()->frequencies.uplinkFollows, UplinkFollowsDial::No);
    }

    void frequenciesAreKeptPerSatellite()
    {
        {
            WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
            QVERIFY(f.connectAndWait());
            QVERIFY(f.loadElementSets(kAllSets));
            QVERIFY(f.rehearseAt(QStringLiteral("2018-01-22T09:00:00Z"), 1.0));
            RadioPanel *panel = radioTab(f);
            DopplerRadio *radio = f.station.radio();
            auto *planBox = in<QGroupBox>(panel, "radioPlanBox");
            QCOMPARE(planBox->title(), QStringLiteral("Frequencies for any satellite tracked"));

            // FLOCK 2P-1 tracked: what is applied is for it, and kept for it.
            QVERIFY(track(f, QStringLiteral("FLOCK 2P-1")));
            QTRY_COMPARE(planBox->title(), QStringLiteral("Frequencies for FLOCK 2P-1 (NORAD 41617)"));
            typeLinearTransponder(panel);
            apply(panel);
            QVERIFY(radio->plan());
            QCOMPARE(radio->plan()->noradId, kFlock);
            untrack(f);
            QTRY_COMPARE(planBox->title(), QStringLiteral("Frequencies for any satellite tracked"));

            // Another satellite with nothing kept: the fields stay, and the
            // panel says the radio's frequencies are another satellite's.
            QVERIFY(track(f, QStringLiteral("JPSS-1")));
            QTRY_COMPARE(planBox->title(), QStringLiteral("Frequencies for JPSS-1 (NORAD 43013)"));
            QCOMPARE(radio->plan()->noradId, kFlock);
            QCOMPARE(in<QLineEdit>(panel, "radioDownlink")->text(), QStringLiteral("435.85M"));
            QVERIFY2(textOf(panel, "radioPlanState").contains(QStringLiteral("Not for the satellite tracked")),
                     qPrintable(textOf(panel, "radioPlanState")));
            type(panel, "radioDownlink", QStringLiteral("7812.5M"));
            type(panel, "radioUplink", QString());
            type(panel, "radioDownlinkOffset", QStringLiteral("+3k"));
            choose(panel, "radioDoppler", QStringLiteral("downlink"));
            apply(panel);
            QCOMPARE(radio->plan()->noradId, kJpss);
            QCOMPARE(radio->plan()->frequencies.downlinkHz, 7812.5e6);
            untrack(f);

            // FLOCK 2P-1 again: its own frequencies and offsets, applied.
            QVERIFY(track(f, QStringLiteral("FLOCK 2P-1")));
            QTRY_COMPARE(radio->plan()->noradId, kFlock);
            QCOMPARE(radio->plan()->frequencies.downlinkHz, 435.85e6);
            QCOMPARE(radio->plan()->frequencies.downlinkOffsetHz, -1200.0);
            QCOMPARE(*radio->plan()->frequencies.uplinkHz, 145.95e6);
            QCOMPARE(in<QLineEdit>(panel, "radioDownlink")->text(), QStringLiteral("435.85M"));
            QCOMPARE(in<QLineEdit>(panel, "radioDownlinkOffset")->text(), QStringLiteral("-1.2k"));
            QCOMPARE(in<QComboBox>(panel, "radioUplinkFollows")->currentData().toString(), QStringLiteral("opposite"));
            // And JPSS-1's, as written.
            QCOMPARE(QSettings().value(QStringLiteral("radio/plans/43013/downlink")).toString(), QStringLiteral("7812.5M"));
            QCOMPARE(QSettings().value(QStringLiteral("radio/plans/43013/downlinkOffset")).toString(), QStringLiteral("+3k"));
            untrack(f);
        }

        // The next start: the frequencies applied last are the radio's again.
        WindowFixture again;
        RadioPanel *panel = radioTab(again);
        DopplerRadio *radio = again.station.radio();
        QVERIFY(radio->plan());
        QCOMPARE(radio->plan()->noradId, kFlock);
        QCOMPARE(radio->plan()->frequencies.downlinkHz, 435.85e6);
        QCOMPARE(in<QLineEdit>(panel, "radioUplink")->text(), QStringLiteral("145.95 MHz"));
        QCOMPARE(in<QComboBox>(panel, "radioTransmitMode")->currentText(), QStringLiteral("LSB"));
    }

    void aSatellitesTranspondersFillTheFields()
    {
        // FLOCK 2P-1 given two transponders in a Gpredict file named after
        // it, loaded through the station's transponder sources as the
        // Refresh button does.
        QTemporaryDir dir;
        QFile trsp(dir.filePath(QStringLiteral("41617.trsp")));
        QVERIFY(trsp.open(QIODevice::WriteOnly));
        trsp.write("[Mode V/U linear]\nUP_LOW=145900000\nUP_HIGH=146000000\nDOWN_LOW=435800000\n"
                   "DOWN_HIGH=435900000\nINVERT=true\nMODE=SSB\n\n[CW beacon]\nDOWN_LOW=435795000\nMODE=CW\n");
        trsp.close();
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.loadElementSets(kAllSets));
        QVERIFY(f.rehearseAt(QStringLiteral("2018-01-22T09:00:00Z"), 1.0));
        slew::radio::TransponderSources *sources = f.station.transponders();
        sources->setUrls({QUrl::fromLocalFile(trsp.fileName())});
        QSignalSpy refreshed(sources, &slew::radio::TransponderSources::finished);
        sources->refresh();
        QVERIFY(refreshed.wait(10000));
        RadioPanel *panel = radioTab(f);
        auto *picker = in<QComboBox>(panel, "radioTransponder");
        QVERIFY(!picker->isEnabled()); // nothing tracked: nothing to pick from
        QVERIFY(in<QPushButton>(panel, "radioRefreshTransponders"));

        // Tracked, with nothing kept for it: its default transponder (the
        // linear one) fills the fields, the middle of the passband and the
        // uplink paired with it, for the operator to Apply.
        QVERIFY(track(f, QStringLiteral("FLOCK 2P-1")));
        QTRY_VERIFY(picker->isEnabled());
        QCOMPARE(picker->count(), 3);
        QCOMPARE(picker->currentIndex(), 1);
        QCOMPARE(in<QLineEdit>(panel, "radioDownlink")->text(), QStringLiteral("435.85M"));
        QCOMPARE(in<QLineEdit>(panel, "radioUplink")->text(), QStringLiteral("145.95M"));
        QCOMPARE(in<QComboBox>(panel, "radioReceiveMode")->currentText(), QStringLiteral("USB"));
        QCOMPARE(in<QComboBox>(panel, "radioTransmitMode")->currentText(), QStringLiteral("LSB"));
        QCOMPARE(in<QComboBox>(panel, "radioUplinkFollows")->currentData().toString(), QStringLiteral("opposite"));

        // The beacon picked: its one frequency, no uplink; a calibration
        // typed before stays the operator's.
        type(panel, "radioDownlinkOffset", QStringLiteral("-700"));
        panel->planForm()->pickTransponder(1);
        QCOMPARE(in<QLineEdit>(panel, "radioDownlink")->text(), QStringLiteral("435.795M"));
        QVERIFY(in<QLineEdit>(panel, "radioUplink")->text().isEmpty());
        QCOMPARE(in<QLineEdit>(panel, "radioDownlinkOffset")->text(), QStringLiteral("-700"));
        apply(panel);
        QVERIFY(f.station.radio()->plan());
        QCOMPARE(f.station.radio()->plan()->frequencies.downlinkHz, 435.795e6);
        QCOMPARE(f.station.radio()->plan()->frequencies.downlinkOffsetHz, -700.0);
        QCOMPARE(f.station.radio()->plan()->receiveMode, QStringLiteral("CW"));
        untrack(f);
    }

    void keepsTransponderSourcesAndFollowsAnotherSlew()
    {
        QTemporaryDir dir;
        auto writeFile = [&](const QString &name, const QByteArray &bytes) {
            QFile file(dir.filePath(name));
            if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
                qWarning("cannot write %s", qPrintable(file.fileName()));
            return file.fileName();
        };
        const QString flock =
            writeFile(QStringLiteral("41617.trsp"), "[Mode V/U linear]\nUP_LOW=145900000\nUP_HIGH=146000000\n"
                                                    "DOWN_LOW=435800000\nDOWN_HIGH=435900000\nINVERT=true\nMODE=SSB\n\n"
                                                    "[CW beacon]\nDOWN_LOW=435795000\n");
        const QString misnamed = writeFile(QStringLiteral("beacon.trsp"), "[CW beacon]\nDOWN_LOW=435795000\n");
        WindowFixture f;
        RadioPanel *panel = radioTab(f);
        slew::radio::TransponderSources *sources = f.station.transponders();
        QTest::mouseClick(in<QPushButton>(panel, "radioTransponderSources"), Qt::LeftButton);
        auto *dialog = panel->findChild<slew::ui::RadioTransponderDialog *>();
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->isVisible());
        auto *field = dialog->findChild<QLineEdit *>(QStringLiteral("radioTransponderSourceField"));
        auto *add = dialog->findChild<QPushButton *>(QStringLiteral("radioAddTransponderSource"));
        auto *refusal = dialog->findChild<QLabel *>(QStringLiteral("radioTransponderSourceRefusal"));
        auto *list = dialog->findChild<QListWidget *>(QStringLiteral("radioTransponderSourceList"));
        QVERIFY(field && add && refusal && list);
        auto addSource = [&](const QString &text) {
            field->setText(text);
            QTest::mouseClick(add, Qt::LeftButton);
        };

        // Refused, each in words saying what was given, and nothing kept.
        const QList<std::pair<QString, QString>> refused{
            {dir.filePath(QStringLiteral("nosuch.trsp")), QStringLiteral("nosuch.trsp': no such file")},
            {misnamed, QStringLiteral("is named after its satellite's catalogue number")},
            {QStringLiteral("ftp://example.org/x.json"), QStringLiteral("'ftp://example.org/x.json': a source is")},
            {QStringLiteral("https:///x.json"), QStringLiteral("names no host")},
        };
        for (const auto &[text, words] : refused) {
            addSource(text);
            QVERIFY2(refusal->isVisible() && refusal->text().contains(words), qPrintable(refusal->text()));
            QVERIFY(sources->urls().isEmpty());
            QVERIFY(!QSettings().contains(QLatin1String(slew::radio::kTransponderUrlsSettingsKey)));
        }

        // A Gpredict file: kept, fetched, and the outcome said on the tab.
        QSignalSpy finished(sources, &slew::radio::TransponderSources::finished);
        addSource(flock);
        QVERIFY(!refusal->isVisible());
        QCOMPARE(sources->urls(), QList<QUrl>{QUrl::fromLocalFile(flock)});
        QCOMPARE(slew::radio::savedTransponderUrls(), sources->urls());
        QVERIFY(finished.wait(10000));
        QTRY_COMPARE(textOf(panel, "radioTransponderState"),
                     QStringLiteral("Transponders refreshed: 2 transponder(s) from 1 source(s)."));
        QCOMPARE(sources->transponders().forSatellite(kFlock).size(), 2);
        QVERIFY2(list->item(0)->text().contains(QStringLiteral("replaced, 2 transponder(s)")),
                 qPrintable(list->item(0)->text()));
        addSource(flock);
        QVERIFY(refusal->text().contains(QStringLiteral("a source already")));

        // A URL nobody answers: the refresh says so on the tab, not only in Events.
        const QString silent = QStringLiteral("http://127.0.0.1:%1/transmitters.json").arg(freeTcpPort());
        addSource(silent);
        QVERIFY(finished.wait(20000));
        QTRY_VERIFY2(textOf(panel, "radioTransponderState").startsWith(QStringLiteral("Transponders: 1 of 2 source(s) "
                                                                                       "not refreshed: ") + silent),
                     qPrintable(textOf(panel, "radioTransponderState")));
        QCOMPARE(sources->transponders().forSatellite(kFlock).size(), 2); // the file's still read
        // Removed: gone from the list kept.
        list->setCurrentRow(1);
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("radioRemoveTransponderSource")),
                          Qt::LeftButton);
        QCOMPARE(sources->urls(), QList<QUrl>{QUrl::fromLocalFile(flock)});
        QCOMPARE(slew::radio::savedTransponderUrls(), sources->urls());
        QTRY_COMPARE(sources->transponders().forSatellite(kFlock).size(), 2);

        // Another Slew (slew --update-transponders: the same class on the
        // same cache, the list saved under the same key) adds a source and
        // refreshes: the window reads both as they land.
        const QString jpss = writeFile(QStringLiteral("43013.trsp"), "[X band]\nDOWN_LOW=7812500000\nMODE=QPSK\n");
        slew::radio::TransponderSources other(slew::radio::transponderCacheDirectory());
        const QList<QUrl> both{QUrl::fromLocalFile(flock), QUrl::fromLocalFile(jpss)};
        slew::radio::saveTransponderUrls(both);
        QSettings().sync();
        other.setUrls(both);
        QSignalSpy otherDone(&other, &slew::radio::TransponderSources::finished);
        other.refresh();
        QVERIFY(otherDone.wait(10000));
        QTRY_COMPARE_WITH_TIMEOUT(sources->urls(), both, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(sources->transponders().forSatellite(kJpss).size(), 1, 5000);
        QTRY_VERIFY2(textOf(panel, "radioTransponderState").contains(QStringLiteral("saved by another Slew")),
                     qPrintable(textOf(panel, "radioTransponderState")));
        QTRY_COMPARE(list->count(), 2);
        // ...and a copy it refreshes, the list unchanged.
        writeFile(QStringLiteral("43013.trsp"),
                  "[X band]\nDOWN_LOW=7812500000\nMODE=QPSK\n\n[S band]\nDOWN_LOW=2247500000\n");
        other.refresh();
        QVERIFY(otherDone.wait(10000));
        QTRY_COMPARE_WITH_TIMEOUT(sources->transponders().forSatellite(kJpss).size(), 2, 5000);
        dialog->close();
    }

    void connectsToRigctldAndSaysWhenItIsLost()
    {
        QProcess rigctld;
        const quint16 port = startHamlibDaemon(rigctld, "rigctld", {"-m", "1"});
        QVERIFY(port);
        const QString uri = QStringLiteral("rigctld://127.0.0.1:%1").arg(port);
        {
            WindowFixture f;
            RadioPanel *panel = radioTab(f);
            DopplerRadio *radio = f.station.radio();
            connectRadio(panel, uri);
            QTRY_VERIFY_WITH_TIMEOUT(radio->link() && radio->link()->isOpen(), 10000);
            // Named once, and the dummy rig's frequency as an operator reads it.
            QTRY_VERIFY2(textOf(panel, "radioLinkState").startsWith(QStringLiteral("Open: ") + uri
                                                                     + QStringLiteral(": open at 145.000 000 MHz; ")),
                         qPrintable(textOf(panel, "radioLinkState")));
            QCOMPARE(textOf(panel, "radioLinkState").count(uri), 1);
            QVERIFY(in<QPushButton>(panel, "radioDisconnect")->isEnabled());
            QCOMPARE(panel->linkBox()->offeredUris().value(0), uri); // the last used first

            // A refusal leaves the open link as it is.
            connectRadio(panel, QStringLiteral("rigctld://127.0.0.1:99999"));
            QVERIFY(refusedWith(panel, "radioLinkRefusal", QStringLiteral("rigctld://127.0.0.1:99999")));
            QCOMPARE(radio->linkUri(), uri);
            QVERIFY(radio->link()->isOpen());
            QVERIFY(textOf(panel, "radioLinkState").startsWith(QStringLiteral("Open: ")));
        }

        // The next start connects again, to the radio kept.
        {
            WindowFixture again;
            RadioPanel *panel = radioTab(again);
            DopplerRadio *radio = again.station.radio();
            QCOMPARE(radio->linkUri(), uri);
            QTRY_VERIFY_WITH_TIMEOUT(radio->link()->isOpen(), 10000);
            QCOMPARE(in<QComboBox>(panel, "radioUri")->currentText(), uri);

            // rigctld goes away: the panel says so, and each try again; the
            // lines for the event log and the status bar name the radio once.
            QSignalSpy said(panel, &RadioPanel::message);
            QVERIFY(endHamlibDaemon(rigctld));
            QTRY_VERIFY2_WITH_TIMEOUT(textOf(panel, "radioLinkState").contains(QStringLiteral("(attempt 2)")),
                                      qPrintable(textOf(panel, "radioLinkState")), 15000);
            QVERIFY(textOf(panel, "radioLinkState").contains(QStringLiteral("trying again in")));
            QVERIFY(textOf(panel, "radioLinkState").count(uri) == 1);
            QStringList lost;
            for (const QList<QVariant> &args : std::as_const(said))
                if (args.at(0).toString().contains(uri))
                    lost << args.at(0).toString();
            QVERIFY(!lost.isEmpty());
            // ("radio: URI: …", or "radio: +f: URI: …" for a command the
            // loss caught on its way, as a loaded machine may see.)
            for (const QString &line : std::as_const(lost))
                QVERIFY2(line.startsWith(QStringLiteral("radio: ")) && line.count(uri) == 1, qPrintable(line));

            QTest::mouseClick(in<QPushButton>(panel, "radioDisconnect"), Qt::LeftButton);
            QTRY_COMPARE(textOf(panel, "radioLinkState"), QStringLiteral("Not connected"));
            QVERIFY(!in<QPushButton>(panel, "radioDisconnect")->isEnabled());
            QCOMPARE(QSettings().value(QStringLiteral("radio/connected")).toBool(), false);
        }
    }

    void tunesAcrossThePassbandFromTheTab()
    {
        // FLOCK 2P-1 given an inverting linear transponder (435.8-435.9 MHz
        // down, 145.9-146.0 MHz up), the radio Hamlib's rigctld (dummy rig).
        QProcess rigctld;
        const quint16 port = startHamlibDaemon(rigctld, "rigctld", {"-m", "1"});
        QVERIFY(port);
        QTemporaryDir dir;
        QFile trsp(dir.filePath(QStringLiteral("41617.trsp")));
        QVERIFY(trsp.open(QIODevice::WriteOnly));
        trsp.write("[Mode V/U linear]\nUP_LOW=145900000\nUP_HIGH=146000000\nDOWN_LOW=435800000\n"
                   "DOWN_HIGH=435900000\nINVERT=true\nMODE=SSB\n");
        trsp.close();
        WindowFixture f;
        QVERIFY(f.connectAndWait());
        QVERIFY(f.loadElementSets(kAllSets));
        slew::radio::TransponderSources *sources = f.station.transponders();
        sources->setUrls({QUrl::fromLocalFile(trsp.fileName())});
        QSignalSpy refreshed(sources, &slew::radio::TransponderSources::finished);
        sources->refresh();
        QVERIFY(refreshed.wait(10000));
        RadioPanel *panel = radioTab(f);
        DopplerRadio *radio = f.station.radio();
        connectRadio(panel, QStringLiteral("rigctld://127.0.0.1:%1").arg(port));
        QTRY_VERIFY_WITH_TIMEOUT(radio->link() && radio->link()->isOpen(), 10000);
        auto *up1k = in<QPushButton>(panel, "radioTuneUp1k");
        QVERIFY(up1k && !up1k->isEnabled()); // no pass tuned: nothing to tune across

        // Tracked: its transponder fills the fields, applied with its passband.
        QVERIFY(f.rehearseAt(QStringLiteral("2018-01-22T09:15:35Z"), 20.0));
        QVERIFY(track(f, QStringLiteral("FLOCK 2P-1")));
        QTRY_COMPARE(in<QLineEdit>(panel, "radioDownlink")->text(), QStringLiteral("435.85M"));
        apply(panel);
        QVERIFY(radio->plan() && radio->plan()->frequencies.downlinkPassband);
        QCOMPARE(radio->plan()->frequencies.downlinkPassband->lowHz, 435.8e6);
        QCOMPARE(radio->plan()->frequencies.downlinkPassband->highHz, 435.9e6);
        f.window->tabs()->setCurrentWidget(panel);
        QTRY_VERIFY_WITH_TIMEOUT(radio->isSteering(), 30000);
        QTRY_VERIFY(up1k->isEnabled());
        const slew::radio::DopplerSteering *steering = radio->steering();
        QTRY_VERIFY(steering->sentReceiveHz() && steering->sentTransmitHz());

        // +1 kHz: the downlink up, the uplink down with it (the transponder
        // inverts); the real radio follows. At 20 times the Doppler moves a
        // few hundred hertz a second: 800 Hz is the step, not the Doppler.
        QSignalSpy read(radio->link(), &slew::radio::RadioLink::frequenciesRead);
        const double receiveBefore = *steering->sentReceiveHz();
        const double transmitBefore = *steering->sentTransmitHz();
        QTest::mouseClick(up1k, Qt::LeftButton);
        QCOMPARE(steering->dialOffsetHz(), 1000.0);
        QCOMPARE(*steering->satellite().uplinkHz, 145.95e6 - 1000);
        auto radioHeld = [&](auto moved) {
            for (const QList<QVariant> &args : std::as_const(read))
                if (moved(args.at(0).value<slew::radio::RadioFrequencies>()))
                    return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(radioHeld([&](const slew::radio::RadioFrequencies &r) {
                                     return r.receiveHz && *r.receiveHz > receiveBefore + 800 && r.transmitHz
                                            && *r.transmitHz < transmitBefore - 800;
                                 }),
                                 5000);
        QTRY_COMPARE(textOf(panel, "radioDial"), QStringLiteral("+1 000 Hz on the downlink, from the plan's"));

        // A notch of the wheel over the frequencies sent: 100 Hz more.
        QWidget *sentLine = in<QWidget>(panel, "radioSent");
        const QPointF middle = QPointF(sentLine->rect().center());
        QWheelEvent notch(middle, sentLine->mapToGlobal(middle), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(sentLine, &notch);
        QCOMPARE(steering->dialOffsetHz(), 1100.0);
        QCOMPARE(*steering->satellite().uplinkHz, 145.95e6 - 1100);

        // Up to the passband's top and no further: said beside the buttons.
        for (int i = 0; i < 60; ++i)
            QTest::mouseClick(up1k, Qt::LeftButton);
        QCOMPARE(steering->dialOffsetHz(), 50000.0);
        QCOMPARE(*steering->satellite().uplinkHz, 145.9e6); // the uplink passband's bottom
        QCOMPARE(textOf(panel, "radioTuneRefusal"), QStringLiteral("Not tuned: at the top of the passband"));
        QTest::mouseClick(in<QPushButton>(panel, "radioTuneDown100"), Qt::LeftButton);
        QCOMPARE(steering->dialOffsetHz(), 49900.0);
        QVERIFY(textOf(panel, "radioTuneRefusal").isEmpty());
        // The offset is the operator's, not an error of the Doppler.
        QTRY_VERIFY2(textOf(panel, "radioFigures").endsWith(QStringLiteral("; dial offset +49 900 Hz")),
                     qPrintable(textOf(panel, "radioFigures")));
        QVERIFY2(radio->figures().worstHz < 1000, qPrintable(textOf(panel, "radioFigures")));

        // Radio control stopped: nothing to tune until resumed.
        QTest::mouseClick(in<QPushButton>(panel, "radioHold"), Qt::LeftButton);
        QVERIFY(!up1k->isEnabled());
        QCOMPARE(radio->tuneBy(1000), QStringLiteral("radio control is stopped"));
        QTest::mouseClick(in<QPushButton>(panel, "radioHold"), Qt::LeftButton);
        QTRY_VERIFY(up1k->isEnabled());

        untrack(f);
        radio->disconnectRadio();
        QVERIFY(endHamlibDaemon(rigctld));
    }

    void showsAndChartsAPassAsTheRadioIsTuned()
    {
        QProcess rigctld;
        const quint16 port = startHamlibDaemon(rigctld, "rigctld", {"-m", "1"});
        QVERIFY(port);
        // The built-in rotator simulator on its own wall clock: the station
        // paces it to the rehearsal.
        WindowFixture f;
        f.window->resize(1280, 720);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.loadElementSets(kAllSets));
        RadioPanel *panel = radioTab(f);
        DopplerRadio *radio = f.station.radio();
        connectRadio(panel, QStringLiteral("rigctld://127.0.0.1:%1").arg(port));
        QTRY_VERIFY_WITH_TIMEOUT(radio->link() && radio->link()->isOpen(), 10000);
        typeLinearTransponder(panel);
        type(panel, "radioDownlinkOffset", QString());
        type(panel, "radioUplinkOffset", QString());
        apply(panel);
        QVERIFY(radio->plan());
        QCOMPARE(textOf(panel, "radioFigures"), QStringLiteral("no pass tuned yet"));
        QCOMPARE(textOf(panel, "radioSent"), QStringLiteral("nothing yet"));

        // Ten seconds (of the station's clock) before AOS, at 20 times.
        QVERIFY(f.rehearseAt(QStringLiteral("2018-01-22T09:15:35Z"), 20.0));
        QVERIFY(track(f, QStringLiteral("FLOCK 2P-1")));
        f.window->bringToFront(panel);
        QSignalSpy steering(radio, &DopplerRadio::steeringChanged);
        QTRY_VERIFY_WITH_TIMEOUT(radio->isSteering(), 30000);

        // Early in the pass the satellite comes closer: the downlink is
        // heard above its frequency, the uplink sent below it.
        QTRY_VERIFY2(textOf(panel, "radioSent").startsWith(QStringLiteral("receive 435.8"))
                         && textOf(panel, "radioSent").contains(QStringLiteral(", transmit 145.9")),
                     qPrintable(textOf(panel, "radioSent")));
        QTRY_VERIFY2(textOf(panel, "radioDopplerNow").startsWith(QStringLiteral("downlink +"))
                         && textOf(panel, "radioDopplerNow").contains(QStringLiteral(", uplink −")),
                     qPrintable(textOf(panel, "radioDopplerNow")));
        QTRY_VERIFY2(textOf(panel, "radioFigures").startsWith(QStringLiteral("this pass: error RMS ")),
                     qPrintable(textOf(panel, "radioFigures")));
        // How fast the shift moves, on both paths: near AOS the downlink
        // falls (the satellite comes closer ever more slowly).
        QTRY_VERIFY2(QRegularExpression(QStringLiteral("^downlink \\+[0-9 ]+ Hz \\(−[0-9 ]+ Hz/s\\), uplink −[0-9 ]+ Hz "
                                                       "\\(\\+[0-9 ]+ Hz/s\\)"))
                         .match(textOf(panel, "radioDopplerNow"))
                         .hasMatch(),
                     qPrintable(textOf(panel, "radioDopplerNow")));
        QCOMPARE(textOf(panel, "radioDial"), QStringLiteral("not turned"));
        const QString firstSent = textOf(panel, "radioSent");
        QTRY_VERIFY(textOf(panel, "radioSent") != firstSent); // it follows the pass

        // Stop radio control: nothing more reaches the radio, until resumed.
        auto *hold = in<QPushButton>(panel, "radioHold");
        QCOMPARE(hold->text(), QStringLiteral("Stop radio control"));
        QTest::mouseClick(hold, Qt::LeftButton);
        QVERIFY(!radio->isSteering());
        QCOMPARE(hold->text(), QStringLiteral("Resume radio control"));
        QSignalSpy sentWhileHeld(radio->link(), &slew::radio::RadioLink::commandSent);
        const double heldAt = f.station.clock()->nowJulian();
        QTRY_VERIFY(f.station.clock()->nowJulian() > heldAt + 20.0 / 86400.0); // 20 s of the pass, at 20 times
        // (A read on the wire when Stop was pressed may finish: it sets nothing.)
        for (const QList<QVariant> &args : std::as_const(sentWhileHeld))
            QVERIFY2(args.at(0).toString().startsWith(QStringLiteral("+f"))
                         || args.at(0).toString().startsWith(QStringLiteral("+i")),
                     qPrintable(args.at(0).toString()));
        QVERIFY(!radio->isSteering());
        QTRY_VERIFY2(textOf(panel, "radioSent").endsWith(QStringLiteral("; radio control stopped")),
                     qPrintable(textOf(panel, "radioSent")));
        QTest::mouseClick(hold, Qt::LeftButton);
        QTRY_VERIFY(radio->isSteering());
        QCOMPARE(hold->text(), QStringLiteral("Stop radio control"));
        QTRY_VERIFY(sentWhileHeld.count() > 0);
        QTRY_VERIFY(!textOf(panel, "radioSent").contains(QStringLiteral("stopped")));
        QTRY_VERIFY(textOf(panel, "radioFigures").startsWith(QStringLiteral("this pass: error RMS ")));
        QTRY_VERIFY(textOf(panel, "radioSent").startsWith(QStringLiteral("receive 435.8")));
        QTRY_VERIFY(radio->figures().samples > 200);
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/radio-tab-during-pass.png")));

        // The tab holds at 1280x720 with every line filled.
        const QString faults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
        QVERIFY2(faults.isEmpty(), qPrintable(faults));

        // The Doppler error on the Telemetry tab, under the pointing error,
        // both paths.
        slew::ui::TelemetryCharts *charts = f.window->telemetryCharts();
        QXYSeries *receive = charts->series(TelemetryRecorder::ReceiveDopplerError);
        QXYSeries *transmit = charts->series(TelemetryRecorder::TransmitDopplerError);
        QVERIFY(receive && transmit);
        auto plotted = [&](QXYSeries *series) {
            charts->redraw();
            return series->count();
        };
        QTRY_VERIFY(plotted(receive) > 5 && plotted(transmit) > 5);
        auto *box = charts->findChild<QWidget *>(QStringLiteral("chartDoppler"));
        QVERIFY(box && !box->isHidden());
        for (const QPointF &p : receive->points())
            QVERIFY2(std::isfinite(p.y()) && std::abs(p.y()) < 1000.0, qPrintable(QString::number(p.y())));
        f.window->bringToFront(charts);
        QVERIFY(f.window->findChild<QWidget *>(QStringLiteral("chartPointing"))->isVisible());
        QVERIFY(box->isVisible());
        QVERIFY(box->geometry().top() > f.window->findChild<QWidget *>(QStringLiteral("chartPointing"))->geometry().top());
        const QString chartFaults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
        QVERIFY2(chartFaults.isEmpty(), qPrintable(chartFaults));
        f.window->bringToFront(panel);

        // LOS (09:27:10): the pass's figures and what was sent last stay.
        QTRY_VERIFY_WITH_TIMEOUT(!radio->isSteering(), 60000);
        QVERIFY2(textOf(panel, "radioFigures").startsWith(QStringLiteral("last pass: error RMS ")),
                 qPrintable(textOf(panel, "radioFigures")));
        QVERIFY(radio->figures().samples > 50);
        QVERIFY(radio->figures().commands > 10);
        QVERIFY(textOf(panel, "radioSent").startsWith(QStringLiteral("receive 435.8")));
        for (const QLabel *label : panel->findChildren<QLabel *>())
            QVERIFY2(!label->text().contains(QStringLiteral("nan"), Qt::CaseInsensitive),
                     qPrintable(label->objectName() + QStringLiteral(": ") + label->text()));
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/radio-tab-after-los.png")));

        untrack(f);
        f.station.radio()->disconnectRadio();
        QVERIFY(endHamlibDaemon(rigctld));
    }
};

QTEST_MAIN(RadioPanelTest)
#include "tst_radiopanel.moc"

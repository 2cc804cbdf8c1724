// Limits (including the 450° overlap and a south stop) and rotator profiles
// (JSON round trip, atomic save, refusing bad files).

#include "model/rotatorlimits.h"
#include "model/rotatorprofile.h"

#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace slew::model;

class ModelTest : public QObject {
    Q_OBJECT
private slots:
    void chooseAzimuth_data();
    void chooseAzimuth();
    void elevationLimits();
    void limitsValidation();
    void profileRoundTrip();
    void profileRefusesBadValues_data();
    void profileRefusesBadValues();
    void profileSaveAndLoad();
    void profileFilesThatAreNotProfiles();
};

void ModelTest::chooseAzimuth_data()
{
    QTest::addColumn<double>("azMin");
    QTest::addColumn<double>("azMax");
    QTest::addColumn<double>("target");
    QTest::addColumn<double>("current"); // NaN: unknown
    QTest::addColumn<double>("expected"); // NaN: refused
    const double none = qQNaN();
    QTest::newRow("plain") << 0.0 << 360.0 << 123.0 << 10.0 << 123.0;
    QTest::newRow("360 from 350") << 0.0 << 360.0 << 360.0 << 350.0 << 360.0;
    QTest::newRow("360 from 10 is 0") << 0.0 << 360.0 << 360.0 << 10.0 << 0.0;
    QTest::newRow("beyond 360 refused") << 0.0 << 360.0 << 400.0 << 10.0 << none;
    QTest::newRow("negative refused") << 0.0 << 360.0 << -10.0 << 10.0 << none;
    QTest::newRow("overlap from 350 to 10 goes on") << 0.0 << 450.0 << 10.0 << 350.0 << 370.0;
    QTest::newRow("overlap from 20 to 10 stays") << 0.0 << 450.0 << 10.0 << 20.0 << 10.0;
    QTest::newRow("overlap 200 single") << 0.0 << 450.0 << 200.0 << 400.0 << 200.0;
    QTest::newRow("overlap unknown prefers base") << 0.0 << 450.0 << 50.0 << none << 50.0;
    QTest::newRow("overlap explicit 420") << 0.0 << 450.0 << 420.0 << 0.0 << 420.0;
    QTest::newRow("south stop -180..180: 350 is -10") << -180.0 << 180.0 << 350.0 << 0.0 << -10.0;
    QTest::newRow("south stop 90 stays") << -180.0 << 180.0 << 90.0 << 0.0 << 90.0;
    QTest::newRow("nan refused") << 0.0 << 360.0 << none << 0.0 << none;
}

void ModelTest::chooseAzimuth()
{
    QFETCH(double, azMin);
    QFETCH(double, azMax);
    QFETCH(double, target);
    QFETCH(double, current);
    QFETCH(double, expected);
    RotatorLimits lim;
    lim.azMin = azMin;
    lim.azMax = azMax;
    const auto choice =
        slew::model::chooseAzimuth(lim, target, std::isnan(current) ? std::nullopt : std::optional<double>(current));
    if (std::isnan(expected)) {
        QVERIFY(!choice.azimuth);
        QVERIFY(!choice.error.isEmpty());
    } else {
        QVERIFY2(choice.azimuth, qPrintable(choice.error));
        QCOMPARE(*choice.azimuth, expected);
    }
}

void ModelTest::elevationLimits()
{
    RotatorLimits lim;
    QVERIFY(checkElevation(lim, 0).isEmpty());
    QVERIFY(checkElevation(lim, 90).isEmpty());
    QVERIFY(checkElevation(lim, 90.0000001).isEmpty()); // rounding noise
    QVERIFY(checkElevation(lim, 90.1).contains("outside"));
    QVERIFY(!checkElevation(lim, -0.1).isEmpty());
    QVERIFY(!checkElevation(lim, qInf()).isEmpty());
    lim.elMax = 180;
    QVERIFY(checkElevation(lim, 179).isEmpty());
}

void ModelTest::limitsValidation()
{
    RotatorLimits lim;
    QVERIFY(lim.validate().isEmpty());
    lim.azMax = 460;
    QVERIFY(!lim.validate().isEmpty());
    lim.azMax = 450;
    QVERIFY(lim.validate().isEmpty());
    QVERIFY(lim.hasOverlap());
    lim.elMax = 200;
    QVERIFY(!lim.validate().isEmpty());
}

void ModelTest::profileRoundTrip()
{
    RotatorProfile p;
    p.name = "Roof G-5500";
    p.uri = "serial:/dev/ttyUSB0?baud=9600";
    p.dialect = slew::protocol::Dialect::SatNogs;
    p.limits.azMax = 450;
    p.limits.elMax = 180;
    p.parkAz = 180;
    p.parkEl = 45;
    p.southStop = true;
    p.azGains = PidGains{1.5, 0.1, 0.05};
    p.deadbandDeg = 1.0;
    p.pollHz = 5;
    p.restPollHz = 0.5;
    p.azOffsetDeg = -2.5;
    p.elOffsetDeg = 0.75;
    p.motion.azSpeedDegS = 3.1;
    p.motion.elSpeedDegS = 1.9;
    p.motion.azAccelDegS2 = 0;
    p.motion.responseDelayS = 1.25;
    p.motion.drive = slew::model::RotatorMotion::Drive::Relay;
    p.motion.trackStepDeg = 1.5;
    QString error;
    const auto back = RotatorProfile::fromJson(p.toJson(), &error);
    QVERIFY2(back, qPrintable(error));
    QCOMPARE(back->name, p.name);
    QCOMPARE(back->uri, p.uri);
    QCOMPARE(back->dialect, p.dialect);
    QCOMPARE(back->limits.azMax, 450.0);
    QCOMPARE(back->limits.elMax, 180.0);
    QCOMPARE(back->parkAz, 180.0);
    QCOMPARE(back->parkEl, 45.0);
    QCOMPARE(back->southStop, true);
    QVERIFY(back->azGains && *back->azGains == *p.azGains);
    QVERIFY(!back->elGains);
    QCOMPARE(back->deadbandDeg, 1.0);
    QCOMPARE(back->pollHz, 5);
    QCOMPARE(back->restPollHz, 0.5);
    QCOMPARE(back->azOffsetDeg, -2.5);
    QCOMPARE(back->elOffsetDeg, 0.75);
    QVERIFY(back->motion == p.motion);
    QCOMPARE(back->firmware, slew::protocol::Firmware::Generic); // SatNOGS's dialect says its firmware
    p.dialect = slew::protocol::Dialect::Gs232B;
    p.firmware = slew::protocol::Firmware::K3ng;
    QCOMPARE(p.toJson().value("firmware").toString(), QStringLiteral("k3ng"));
    QCOMPARE(RotatorProfile::fromJson(p.toJson(), &error)->firmware, slew::protocol::Firmware::K3ng);
    // A controller built with its own stop tolerance: kept, each axis apart.
    QVERIFY(!p.toJson().contains("stopTolerance"));
    p.stopToleranceAzDeg = 1.5;
    const auto tolerant = RotatorProfile::fromJson(p.toJson(), &error);
    QVERIFY2(tolerant, qPrintable(error));
    QCOMPARE(tolerant->stopToleranceAzDeg, std::optional<double>(1.5));
    QVERIFY(!tolerant->stopToleranceElDeg);
    // A profile written before offsets and motion existed reads with none
    // and a G-5500's figures.
    const auto old = RotatorProfile::fromJson(QJsonDocument::fromJson(R"({"name":"old"})").object(), &error);
    QVERIFY(old);
    QCOMPARE(old->azOffsetDeg, 0.0);
    QVERIFY(old->motion == slew::model::RotatorMotion{});
    QCOMPARE(old->restPollHz, 1.0); // a station at rest is polled once a second
}

void ModelTest::profileRefusesBadValues_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    QTest::newRow("dialect") << QByteArray(R"({"dialect":"gs232"})") << "unknown dialect";
    QTest::newRow("firmware") << QByteArray(R"({"firmware":"grbl"})") << "unknown firmware 'grbl'";
    QTest::newRow("firmware for another dialect") << QByteArray(R"({"dialect":"easycomm3","firmware":"k3ng"})")
                                                  << "k3ng speaks easycomm2, gs232a or gs232b, not easycomm3";
    QTest::newRow("stop tolerance") << QByteArray(R"({"stopTolerance":{"az":30}})") << "stop tolerance must be 0° to 10°";
    QTest::newRow("stop tolerance, not a number") << QByteArray(R"({"stopTolerance":{"el":"1"}})") << "'el' must be a number";
    QTest::newRow("az max") << QByteArray(R"({"limits":{"azMax":720}})") << "more than 450";
    QTest::newRow("string number") << QByteArray(R"({"limits":{"azMax":"360"}})") << "must be a number";
    QTest::newRow("park outside") << QByteArray(R"({"park":{"az":10,"el":120}})") << "park position";
    QTest::newRow("gains") << QByteArray(R"({"azGains":[1,2,3]})") << "kp, ki, kd";
    QTest::newRow("poll") << QByteArray(R"({"pollHz":500})") << "poll rate";
    QTest::newRow("rest poll too slow") << QByteArray(R"({"restPollHz":0.01})") << "poll rate at rest";
    QTest::newRow("rest poll above the poll") << QByteArray(R"({"pollHz":2,"restPollHz":5})") << "poll rate at rest";
    QTest::newRow("az offset") << QByteArray(R"({"offsets":{"az":200}})") << "azimuth offset";
    QTest::newRow("el offset") << QByteArray(R"({"offsets":{"el":-25}})") << "elevation offset";
    QTest::newRow("speed") << QByteArray(R"({"motion":{"azSpeedDegS":0}})") << "axis speeds";
    QTest::newRow("delay") << QByteArray(R"({"motion":{"responseDelayS":-1}})") << "response delay";
    QTest::newRow("drive") << QByteArray(R"({"motion":{"drive":"stepper"}})") << "drive must be";
    QTest::newRow("step") << QByteArray(R"({"motion":{"trackStepDeg":20}})") << "tracking step";
}

void ModelTest::profileRefusesBadValues()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!RotatorProfile::fromJson(QJsonDocument::fromJson(json).object(), &error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

void ModelTest::profileSaveAndLoad()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("rotator.json");
    RotatorProfile p;
    p.name = "Test";
    QString error;
    QVERIFY2(p.save(path, &error), qPrintable(error));
    const auto loaded = RotatorProfile::load(path, &error);
    QVERIFY2(loaded, qPrintable(error));
    QCOMPARE(loaded->name, QStringLiteral("Test"));

    // A corrupt file is refused with the path in the message; the old file
    // is untouched by a failed save into a directory that does not exist.
    QFile bad(dir.filePath("bad.json"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("{ not json");
    bad.close();
    QVERIFY(!RotatorProfile::load(bad.fileName(), &error));
    QVERIFY(error.contains("bad.json"));
    QVERIFY(!RotatorProfile::load(dir.filePath("missing.json"), &error));
    QVERIFY(!p.save(dir.filePath("no/such/dir/x.json"), &error));
    QVERIFY(RotatorProfile::load(path, &error));
}

void ModelTest::profileFilesThatAreNotProfiles()
{
    QTemporaryDir dir;
    QString error;
    // A device reads 0 to QFile::size() and then for ever.
    QVERIFY(!RotatorProfile::load("/dev/zero", &error));
    QCOMPARE(error, QStringLiteral("/dev/zero is a character device, not a file; name a regular file"));
    // A FIFO with no writer would block open().
    const QString fifo = dir.filePath("profile.fifo");
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    QVERIFY(!RotatorProfile::load(fifo, &error));
    QVERIFY2(error.contains("FIFO"), qPrintable(error));
    // A JSON array is well-formed JSON, just not a profile: the message says
    // that, never "no error occurred".
    QFile array(dir.filePath("array.json"));
    QVERIFY(array.open(QIODevice::WriteOnly));
    array.write("[1, 2, 3]");
    array.close();
    QVERIFY(!RotatorProfile::load(array.fileName(), &error));
    QVERIFY2(error.contains("the file holds JSON an array, a profile is a JSON object"), qPrintable(error));
    QVERIFY2(!error.contains("no error"), qPrintable(error));
    // Over the cap.
    QFile big(dir.filePath("big.json"));
    QVERIFY(big.open(QIODevice::WriteOnly));
    big.write("{\"name\": \"" + QByteArray(RotatorProfile::kLargestProfile, 'x') + "\"}");
    big.close();
    QVERIFY(!RotatorProfile::load(big.fileName(), &error));
    QVERIFY2(error.contains("over the 1 MiB limit"), qPrintable(error));
}

QTEST_GUILESS_MAIN(ModelTest)
#include "tst_model.moc"

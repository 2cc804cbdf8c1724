// Links made from URIs: parsing errors name the URI and the cause; a TCP link
// opens, refuses and loses; a serial link works on a real pseudo-terminal pair
// made by socat, and reports the far end going away.

#include "transport/linkfactory.h"
#include "transport/seriallink.h"
#include "transport/serialports.h"

#include <QFile>
#include <QProcess>
#include <QSerialPort>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

using namespace slew::transport;

class LinksTest : public QObject {
    Q_OBJECT
private slots:
    void badUris_data();
    void badUris();
    void serialOptionsAreRead();
    void tcpOpensAndIsLost();
    void tcpRefused();
    void serialOverPseudoTerminalPair();
    void registeredSchemeIsUsed();
    void portListing();
};

void LinksTest::badUris_data()
{
    QTest::addColumn<QString>("uri");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << "" << "no link given";
    QTest::newRow("no scheme") << "/dev/ttyUSB0" << "no scheme";
    QTest::newRow("unknown scheme") << "gopher://x" << "unknown link kind 'gopher'";
    QTest::newRow("serial no port") << "serial:" << "no serial port named";
    QTest::newRow("serial bad baud") << "serial:/dev/ttyUSB0?baud=0" << "baud rate '0'";
    QTest::newRow("serial bad parity") << "serial:/dev/ttyUSB0?parity=maybe" << "parity must be";
    QTest::newRow("serial bad data") << "serial:/dev/ttyUSB0?data=9" << "data bits must be 5 to 8";
    QTest::newRow("serial bad stop") << "serial:/dev/ttyUSB0?stop=3" << "stop bits must be";
    QTest::newRow("serial bad flow") << "serial:/dev/ttyUSB0?flow=pigeon" << "flow must be";
    QTest::newRow("serial unknown item") << "serial:/dev/ttyUSB0?speed=9600" << "unknown serial option 'speed'";
    QTest::newRow("serial empty dialect") << "serial:/dev/ttyUSB0?dialect=" << "dialect names nothing";
    QTest::newRow("tcp empty firmware") << "tcp://localhost:4533?firmware=" << "firmware names nothing";
    QTest::newRow("tcp no host") << "tcp://:4533" << "no host";
    QTest::newRow("tcp no port") << "tcp://localhost" << "no port";
}

void LinksTest::badUris()
{
    QFETCH(QString, uri);
    QFETCH(QString, message);
    const LinkResult r = createLink(uri);
    QVERIFY(!r.link);
    QVERIFY2(r.error.contains(message), qPrintable(r.error));
    if (!uri.isEmpty())
        QVERIFY2(r.error.contains(uri), qPrintable(r.error));
}

void LinksTest::serialOptionsAreRead()
{
    LinkResult r = createLink("serial:/dev/ttyUSB7?baud=9600&data=7&parity=even&stop=2&flow=rtscts");
    QVERIFY2(r.link, qPrintable(r.error));
    auto *serial = qobject_cast<SerialLink *>(r.link.get());
    QVERIFY(serial);
    QCOMPARE(serial->settings().portName, QStringLiteral("/dev/ttyUSB7"));
    QCOMPARE(serial->settings().baud, 9600);
    QCOMPARE(serial->settings().dataBits, QSerialPort::Data7);
    QCOMPARE(serial->settings().parity, QSerialPort::EvenParity);
    QCOMPARE(serial->settings().stopBits, QSerialPort::TwoStop);
    QCOMPARE(serial->settings().flow, QSerialPort::HardwareControl);
    // What the controller speaks and runs, named in the URI itself.
    r = createLink("serial:/dev/ttyUSB7?baud=9600&dialect=GS232B&firmware=k3ng");
    QVERIFY2(r.link, qPrintable(r.error));
    QCOMPARE(r.link->hints().dialect, QStringLiteral("gs232b"));
    QCOMPARE(r.link->hints().firmware, QStringLiteral("k3ng"));
    r = createLink("tcp://127.0.0.1:4533?dialect=satnogs");
    QVERIFY2(r.link, qPrintable(r.error));
    QCOMPARE(r.link->hints().dialect, QStringLiteral("satnogs"));
    QVERIFY(r.link->hints().firmware.isEmpty());
    // Defaults: 19200 8N1, as Hamlib's Easycomm backends.
    r = createLink("serial:/dev/ttyUSB0");
    serial = qobject_cast<SerialLink *>(r.link.get());
    QCOMPARE(serial->settings().baud, 19200);
    QCOMPARE(serial->settings().dataBits, QSerialPort::Data8);
    QCOMPARE(serial->settings().parity, QSerialPort::NoParity);

    // A port that does not exist fails with the URI and the cause, later.
    r = createLink("serial:/dev/slew-no-such-port");
    QSignalSpy failed(r.link.get(), &Link::failed);
    r.link->open();
    QVERIFY(failed.wait(2000));
    QVERIFY(failed.first().at(0).toString().contains("serial:/dev/slew-no-such-port"));
}

void LinksTest::tcpOpensAndIsLost()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    LinkResult r = createLink(QStringLiteral("tcp://127.0.0.1:%1").arg(server.serverPort()));
    QVERIFY(r.link);
    QSignalSpy opened(r.link.get(), &Link::opened);
    QSignalSpy lost(r.link.get(), &Link::lost);
    r.link->open();
    QVERIFY(opened.wait(2000));
    QVERIFY(r.link->isOpen());
    QTRY_VERIFY(server.hasPendingConnections());
    QTcpSocket *peer = server.nextPendingConnection();
    r.link->device()->write("AZ EL\n");
    QByteArray atPeer;
    QTRY_COMPARE(atPeer += peer->readAll(), QByteArray("AZ EL\n"));
    peer->abort();
    QVERIFY(lost.wait(2000));
    QVERIFY(lost.first().at(0).toString().contains("closed"));
    QVERIFY(!r.link->isOpen());
}

void LinksTest::tcpRefused()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    const quint16 port = server.serverPort();
    server.close();
    LinkResult r = createLink(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
    QSignalSpy failed(r.link.get(), &Link::failed);
    r.link->open();
    QVERIFY(failed.wait(5000));
    QVERIFY2(failed.first().at(0).toString().contains("refused", Qt::CaseInsensitive),
             qPrintable(failed.first().at(0).toString()));
}

void LinksTest::serialOverPseudoTerminalPair()
{
    const QString socat = QStandardPaths::findExecutable("socat");
    QVERIFY2(!socat.isEmpty(), "socat is not installed: packaging/dev.sh installs it");
    QTemporaryDir dir;
    const QString a = dir.filePath("a"), b = dir.filePath("b");
    QProcess pair;
    pair.start(socat, {"pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b});
    QTRY_VERIFY(QFile::exists(a) && QFile::exists(b));

    LinkResult r = createLink("serial:" + a + "?baud=19200");
    QVERIFY2(r.link, qPrintable(r.error));
    QSignalSpy opened(r.link.get(), &Link::opened);
    QSignalSpy lost(r.link.get(), &Link::lost);
    r.link->open();
    QVERIFY(opened.wait(2000));

    QSerialPort far;
    far.setPortName(b);
    QVERIFY(far.open(QIODevice::ReadWrite));
    r.link->device()->write("AZ EL\n");
    QByteArray atFar;
    QTRY_COMPARE(atFar += far.readAll(), QByteArray("AZ EL\n"));
    far.write("AZ10.0 EL20.0\n");
    QByteArray got;
    QTRY_COMPARE(got += r.link->device()->readAll(), QByteArray("AZ10.0 EL20.0\n"));

    // The far end vanishing (socat ends, like a USB adapter pulled out) is a loss.
    far.close();
    pair.terminate();
    QTRY_COMPARE(pair.state(), QProcess::NotRunning);
    r.link->device()->write("GS\n");
    QTRY_VERIFY_WITH_TIMEOUT(!lost.isEmpty(), 5000);
    QVERIFY(lost.first().at(0).toString().contains("serial"));
}

void LinksTest::registeredSchemeIsUsed()
{
    bool called = false;
    registerLinkScheme("testonly", [&](const QUrl &url, const QString &uri) {
        called = true;
        return LinkResult{nullptr, uri + ": made for " + url.path()};
    });
    QVERIFY(isSchemeRegistered("testonly"));
    const LinkResult r = createLink("testonly:thing");
    QVERIFY(called);
    QCOMPARE(r.error, QStringLiteral("testonly:thing: made for thing"));
}

void LinksTest::portListing()
{
    // Whatever the machine has; every entry has a name and a usable URI.
    for (const SerialPortDescription &p : availableSerialPorts()) {
        QVERIFY(!p.portName.isEmpty());
        QVERIFY(createLink(p.uri()).link);
    }
    QCOMPARE(commonBaudRates().first(), 19200);
}

QTEST_GUILESS_MAIN(LinksTest)
#include "tst_links.moc"

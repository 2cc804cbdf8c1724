#include "linkfactory.h"

#include "seriallink.h"
#include "tcplink.h"

#include <QHash>
#include <QUrlQuery>

namespace slew::transport {

namespace {

QHash<QString, LinkMaker> &registry()
{
    static QHash<QString, LinkMaker> makers;
    return makers;
}

LinkResult fail(const QString &uri, const QString &why)
{
    return {nullptr, QObject::tr("%1: %2").arg(uri, why)};
}

// `checksum=1` (or 0) turns the XOR checksum on for the link (link.h).
// Returns an error for any other value.
QString readChecksum(QStringView value, LinkHints *hints)
{
    if (value == u"1" || value == u"on" || value == u"true" || value == u"yes") {
        hints->checksum = true;
        return {};
    }
    if (value == u"0" || value == u"off" || value == u"false" || value == u"no") {
        hints->checksum = false;
        return {};
    }
    return QObject::tr("checksum must be 1 or 0, not '%1'").arg(value);
}

// `rotor=n`: the rotor of a multi-rotor controller this link drives (link.h).
QString readRotor(QStringView value, LinkHints *hints)
{
    bool ok = false;
    const int n = value.toInt(&ok);
    if (!ok || n < 1 || n > 4)
        return QObject::tr("rotor must be 1 to 4, not '%1'").arg(value);
    hints->rotor = n;
    return {};
}

QString readBaud(QStringView value, LinkHints *hints)
{
    bool ok = false;
    const int baud = value.toInt(&ok);
    if (!ok || baud < 50 || baud > 4000000)
        return QObject::tr("baud rate '%1' is not a rate").arg(value);
    hints->baud = baud;
    return {};
}

// `dialect=gs232b` and `firmware=k3ng`: what the controller at the far end
// speaks and runs, so a URI alone says it (the names of --dialect and the
// profile). Kept as written, lower-cased: the names are the protocol's,
// which the session checks before it opens the link (session/connectionplan.h).
QString readName(const char *what, QStringView value, QString *into)
{
    if (value.trimmed().isEmpty())
        return QObject::tr("%1 names nothing").arg(QLatin1String(what));
    *into = value.trimmed().toString().toLower();
    return {};
}

LinkResult withHints(std::unique_ptr<Link> link, const LinkHints &hints)
{
    link->setHints(hints);
    return {std::move(link), {}};
}

LinkResult makeSerial(const QUrl &url, const QString &uri)
{
    LinkHints hints;
    SerialSettings s;
    s.portName = url.path();
    if (s.portName.isEmpty())
        return fail(uri, QObject::tr("no serial port named (expected serial:/dev/ttyUSB0)"));

    const QUrlQuery query(url);
    for (const auto &[key, value] : query.queryItems()) {
        bool ok = false;
        if (key == QLatin1String("baud")) {
            s.baud = value.toInt(&ok);
            if (!ok || s.baud < 50 || s.baud > 4000000)
                return fail(uri, QObject::tr("baud rate '%1' is not a rate").arg(value));
        } else if (key == QLatin1String("data")) {
            const int bits = value.toInt(&ok);
            if (!ok || bits < 5 || bits > 8)
                return fail(uri, QObject::tr("data bits must be 5 to 8, not '%1'").arg(value));
            s.dataBits = QSerialPort::DataBits(bits);
        } else if (key == QLatin1String("parity")) {
            static const QHash<QString, QSerialPort::Parity> parities{
                {"none", QSerialPort::NoParity}, {"even", QSerialPort::EvenParity}, {"odd", QSerialPort::OddParity},
                {"mark", QSerialPort::MarkParity}, {"space", QSerialPort::SpaceParity}};
            if (!parities.contains(value))
                return fail(uri, QObject::tr("parity must be none, even, odd, mark or space, not '%1'").arg(value));
            s.parity = parities.value(value);
        } else if (key == QLatin1String("stop")) {
            if (value == QLatin1String("1"))
                s.stopBits = QSerialPort::OneStop;
            else if (value == QLatin1String("1.5"))
                s.stopBits = QSerialPort::OneAndHalfStop;
            else if (value == QLatin1String("2"))
                s.stopBits = QSerialPort::TwoStop;
            else
                return fail(uri, QObject::tr("stop bits must be 1, 1.5 or 2, not '%1'").arg(value));
        } else if (key == QLatin1String("flow")) {
            if (value == QLatin1String("none"))
                s.flow = QSerialPort::NoFlowControl;
            else if (value == QLatin1String("rtscts") || value == QLatin1String("hardware"))
                s.flow = QSerialPort::HardwareControl;
            else if (value == QLatin1String("xonxoff") || value == QLatin1String("software"))
                s.flow = QSerialPort::SoftwareControl;
            else
                return fail(uri, QObject::tr("flow must be none, rtscts or xonxoff, not '%1'").arg(value));
        } else if (key == QLatin1String("checksum")) {
            if (const QString e = readChecksum(value, &hints); !e.isEmpty())
                return fail(uri, e);
        } else if (key == QLatin1String("rotor")) {
            if (const QString e = readRotor(value, &hints); !e.isEmpty())
                return fail(uri, e);
        } else if (key == QLatin1String("dialect")) {
            if (const QString e = readName("dialect", value, &hints.dialect); !e.isEmpty())
                return fail(uri, e);
        } else if (key == QLatin1String("firmware")) {
            if (const QString e = readName("firmware", value, &hints.firmware); !e.isEmpty())
                return fail(uri, e);
        } else {
            return fail(uri, QObject::tr("unknown serial option '%1' (known: baud, data, parity, stop, flow, checksum, "
                                         "rotor, dialect, firmware)")
                                 .arg(key));
        }
    }
    hints.baud = s.baud;
    return withHints(std::make_unique<SerialLink>(uri, s), hints);
}

LinkResult makeTcp(const QUrl &url, const QString &uri)
{
    if (url.host().isEmpty())
        return fail(uri, QObject::tr("no host named (expected tcp://host:port)"));
    if (url.port() <= 0)
        return fail(uri, QObject::tr("no port named (expected tcp://host:port)"));
    LinkHints hints;
    for (const auto &[key, value] : QUrlQuery(url).queryItems()) {
        QString e;
        if (key == QLatin1String("checksum"))
            e = readChecksum(value, &hints);
        else if (key == QLatin1String("rotor"))
            e = readRotor(value, &hints);
        else if (key == QLatin1String("baud")) // the serial line behind a network adapter, for pacing
            e = readBaud(value, &hints);
        else if (key == QLatin1String("dialect"))
            e = readName("dialect", value, &hints.dialect);
        else if (key == QLatin1String("firmware"))
            e = readName("firmware", value, &hints.firmware);
        else
            return fail(uri, QObject::tr("unknown tcp option '%1' (known: checksum, rotor, baud, dialect, firmware)")
                                 .arg(key));
        if (!e.isEmpty())
            return fail(uri, e);
    }
    return withHints(std::make_unique<TcpLink>(uri, url.host(), quint16(url.port())), hints);
}

void registerBuiltIns()
{
    static bool done = false;
    if (done)
        return;
    done = true;
    registry().insert(QStringLiteral("serial"), makeSerial);
    registry().insert(QStringLiteral("tcp"), makeTcp);
}

} // namespace

void registerLinkScheme(const QString &scheme, LinkMaker maker)
{
    registerBuiltIns();
    registry().insert(scheme.toLower(), std::move(maker));
}

bool isSchemeRegistered(const QString &scheme)
{
    registerBuiltIns();
    return registry().contains(scheme.toLower());
}

LinkResult createLink(const QString &uri)
{
    registerBuiltIns();
    const QString trimmed = uri.trimmed();
    if (trimmed.isEmpty())
        return {nullptr, QObject::tr("no link given (expected serial:, tcp:// or sim:)")};
    const QUrl url(trimmed, QUrl::StrictMode);
    if (!url.isValid())
        return fail(trimmed, QObject::tr("not a valid URI: %1").arg(url.errorString()));
    const QString scheme = url.scheme().toLower();
    if (scheme.isEmpty())
        return fail(trimmed, QObject::tr("no scheme (expected serial:, tcp:// or sim:)"));
    const auto maker = registry().constFind(scheme);
    if (maker == registry().constEnd()) {
        QStringList known = registry().keys();
        known.sort();
        return fail(trimmed, QObject::tr("unknown link kind '%1' (known: %2)").arg(scheme, known.join(", ")));
    }
    return (*maker)(url, trimmed);
}

LinkHints linkHintsFor(const QString &uri)
{
    const LinkResult made = createLink(uri);
    return made.link ? made.link->hints() : LinkHints{};
}

} // namespace slew::transport

#include "rotor/connectionbar.h"

#include "session/connectionplan.h"
#include "transport/serialports.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QToolButton>
#include <QUrl>
#include <QUrlQuery>

namespace slew::ui {

using session::RotatorSession;

namespace {

enum Kind { Simulator, Serial, Tcp, Custom };

const char *kUriKey = "connection/uri";
const char *kDialectKey = "connection/dialect";

QWidget *row(std::initializer_list<QWidget *> widgets)
{
    auto *w = new QWidget;
    auto *l = new QHBoxLayout(w);
    l->setContentsMargins(0, 0, 0, 0);
    for (QWidget *child : widgets)
        l->addWidget(child);
    return w;
}

} // namespace

ConnectionBar::ConnectionBar(RotatorSession *session, QWidget *parent) : QWidget(parent), m_session(session)
{
    setObjectName(QStringLiteral("connectionBar"));
    m_kind = new QComboBox;
    m_kind->setObjectName(QStringLiteral("connectionKind"));
    m_kind->addItems({tr("Simulator"), tr("Serial port"), tr("Network (TCP)"), tr("URI")});

    m_simUri = new QLineEdit(QStringLiteral("sim:"));
    m_simUri->setObjectName(QStringLiteral("simulatorUri"));
    m_simUri->setToolTip(tr("Simulator options, e.g. sim:?az_max=450&jam=az"));

    m_serialPort = new QComboBox;
    m_serialPort->setObjectName(QStringLiteral("serialPort"));
    m_serialPort->setEditable(true);
    m_serialPort->setMinimumContentsLength(14);
    auto *refresh = new QToolButton;
    refresh->setObjectName(QStringLiteral("refreshSerialPorts"));
    refresh->setText(QStringLiteral("↻"));
    refresh->setToolTip(tr("Look for serial ports again"));
    connect(refresh, &QToolButton::clicked, this, &ConnectionBar::refreshSerialPorts);
    m_baud = new QComboBox;
    m_baud->setObjectName(QStringLiteral("serialBaud"));
    for (qint32 baud : transport::commonBaudRates())
        m_baud->addItem(QString::number(baud), baud);
    // SPID's own rates, slower than any a line protocol uses: listed last.
    for (qint32 baud : {600, 1200})
        m_baud->addItem(QString::number(baud), baud);
    m_baud->setCurrentText(QStringLiteral("19200"));

    m_tcpHost = new QLineEdit(QStringLiteral("localhost"));
    m_tcpHost->setObjectName(QStringLiteral("tcpHost"));
    m_tcpPort = new QSpinBox;
    m_tcpPort->setObjectName(QStringLiteral("tcpPort"));
    m_tcpPort->setRange(1, 65535);
    m_tcpPort->setValue(4533);

    m_customUri = new QLineEdit;
    m_customUri->setObjectName(QStringLiteral("customUri"));
    m_customUri->setPlaceholderText(QStringLiteral("serial:/dev/ttyUSB0?baud=9600, tcp://host:port, sim:?..."));

    m_fields = new QStackedWidget;
    m_fields->addWidget(m_simUri);
    m_fields->addWidget(row({m_serialPort, refresh, m_baud}));
    m_fields->addWidget(row({m_tcpHost, new QLabel(QStringLiteral(":")), m_tcpPort}));
    m_fields->addWidget(m_customUri);
    m_fields->setMinimumWidth(300);
    connect(m_kind, &QComboBox::currentIndexChanged, m_fields, &QStackedWidget::setCurrentIndex);

    m_dialect = new QComboBox;
    m_dialect->setObjectName(QStringLiteral("dialect"));
    for (auto d : protocol::allDialects())
        m_dialect->addItem(protocol::dialectName(d), int(d));
    setDialect(protocol::Dialect::Easycomm3);
    // A Rot2Prog runs at 600 baud and a Rot1Prog at 1200, whatever else:
    // choosing one sets the rate it needs (the MD-01/02 is set up per unit).
    connect(m_dialect, &QComboBox::activated, this, [this] {
        if (dialect() == protocol::Dialect::Rot2Prog)
            m_baud->setCurrentText(QStringLiteral("600"));
        else if (dialect() == protocol::Dialect::Rot1Prog)
            m_baud->setCurrentText(QStringLiteral("1200"));
    });
    m_dialect->setToolTip(tr("Which protocol the controller speaks: an Easycomm flavour, Yaesu GS-232, rotctld "
                             "(chosen for you on a rotctld:// link), the Micro-2g, or SPID (Rot2Prog, Rot1Prog, "
                             "MD-01/02)"));

    m_connect = new QPushButton(tr("Connect"));
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_connect->setDefault(false);
    m_connect->setAutoDefault(false);
    connect(m_connect, &QPushButton::clicked, this, [this] {
        if (m_session->state() == RotatorSession::State::Disconnected)
            connectToRotator();
        else
            disconnectFromRotator();
    });

    m_light = new QLabel;
    m_light->setFixedSize(14, 14);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("connectionState"));
    m_state->setMinimumWidth(110);
    m_version = new QLabel;
    m_version->setObjectName(QStringLiteral("deviceVersion"));
    m_version->setToolTip(tr("The controller's version (VE)"));

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->addWidget(m_kind);
    layout->addWidget(m_fields, 1);
    layout->addWidget(new QLabel(tr("Dialect")));
    layout->addWidget(m_dialect);
    layout->addWidget(m_connect);
    layout->addSpacing(12);
    layout->addWidget(m_light);
    layout->addWidget(m_state);
    layout->addWidget(m_version);

    refreshSerialPorts();
    connect(session, &RotatorSession::stateChanged, this, &ConnectionBar::onStateChanged);
    connect(session, &RotatorSession::versionChanged, this,
            [this](const QString &v) { m_version->setText(v.isEmpty() ? QString() : tr("Device: %1").arg(v)); });
    onStateChanged(session->state(), {});
}

void ConnectionBar::refreshSerialPorts()
{
    const QString current = m_serialPort->currentText();
    m_serialPort->clear();
    for (const auto &port : transport::availableSerialPorts())
        m_serialPort->addItem(port.location, port.description);
    if (!current.isEmpty())
        m_serialPort->setCurrentText(current);
}

QString ConnectionBar::uri() const
{
    switch (m_kind->currentIndex()) {
    case Simulator:
        return m_simUri->text().trimmed();
    case Serial:
        return QStringLiteral("serial:%1?baud=%2").arg(m_serialPort->currentText().trimmed(), m_baud->currentText());
    case Tcp:
        return QStringLiteral("tcp://%1:%2").arg(m_tcpHost->text().trimmed()).arg(m_tcpPort->value());
    default:
        return m_customUri->text().trimmed();
    }
}

void ConnectionBar::setUri(const QString &uri)
{
    const QUrl url(uri);
    int kind = Custom;
    if (uri.startsWith(QLatin1String("sim:"))) {
        m_simUri->setText(uri);
        kind = Simulator;
    } else if (url.scheme() == QLatin1String("tcp") && !url.host().isEmpty() && url.port() > 0 && !url.hasQuery()) {
        // (a query, `?firmware=k3ng`, keeps the whole URI as it was written)
        m_tcpHost->setText(url.host());
        m_tcpPort->setValue(url.port());
        kind = Tcp;
    } else if (url.scheme() == QLatin1String("serial") && !url.path().isEmpty()) {
        const QString baud = QUrlQuery(url).queryItemValue(QStringLiteral("baud"));
        const QStringList otherItems = [&] {
            QStringList keys;
            for (const auto &item : QUrlQuery(url).queryItems())
                if (item.first != QLatin1String("baud"))
                    keys << item.first;
            return keys;
        }();
        if (otherItems.isEmpty()) {
            m_serialPort->setCurrentText(url.path());
            if (!baud.isEmpty())
                m_baud->setCurrentText(baud);
            kind = Serial;
        }
    }
    if (kind == Custom)
        m_customUri->setText(uri);
    m_kind->setCurrentIndex(kind);
}

protocol::Dialect ConnectionBar::dialect() const
{
    return protocol::Dialect(m_dialect->currentData().toInt());
}

void ConnectionBar::setDialect(protocol::Dialect d)
{
    m_dialect->setCurrentIndex(m_dialect->findData(int(d)));
}

QString ConnectionBar::rememberedUri()
{
    return QSettings().value(QLatin1String(kUriKey)).toString();
}

std::optional<protocol::Dialect> ConnectionBar::rememberedDialect()
{
    return protocol::dialectFromName(QSettings().value(QLatin1String(kDialectKey)).toString());
}

void ConnectionBar::connectToRotator()
{
    const QString target = uri();
    if (target.isEmpty()) {
        showState(tr("no address"), QColor(0xe5, 0x48, 0x48), tr("Fill in where the rotator is first."));
        return;
    }
    const model::RotatorProfile profile =
        session::windowConnectionProfile(target, m_session->profile(), dialect(), m_session->uri());
    setDialect(profile.dialect); // the link's, where it names one
    m_session->setProfile(profile);
    m_operatorDisconnected = false;
    m_everConnected = false;
    m_version->clear();
    m_session->connectTo(target);
}

void ConnectionBar::disconnectFromRotator()
{
    m_operatorDisconnected = true;
    emit disconnectRequested();
    m_session->disconnectFromRotator();
}

void ConnectionBar::showState(const QString &text, const QColor &colour, const QString &detail)
{
    m_state->setText(text);
    m_state->setToolTip(detail);
    m_light->setStyleSheet(QStringLiteral("background:%1; border-radius:7px; border:1px solid #222;").arg(colour.name()));
}

void ConnectionBar::onStateChanged(RotatorSession::State state, const QString &detail)
{
    const bool idle = state == RotatorSession::State::Disconnected;
    m_connect->setText(idle ? tr("Connect") : tr("Disconnect"));
    for (QWidget *w : {static_cast<QWidget *>(m_kind), static_cast<QWidget *>(m_fields),
                       static_cast<QWidget *>(m_dialect)})
        w->setEnabled(idle);
    switch (state) {
    case RotatorSession::State::Connecting:
        showState(tr("connecting…"), QColor(0xf2, 0xc0, 0x3c), detail);
        break;
    case RotatorSession::State::Reconnecting:
        showState(tr("reconnecting…"), QColor(0xf2, 0x9a, 0x3c), detail);
        break;
    case RotatorSession::State::Connected: {
        m_everConnected = true;
        showState(tr("connected"), QColor(0x4c, 0xd9, 0x64), detail);
        QSettings settings;
        settings.setValue(QLatin1String(kUriKey), m_session->uri());
        settings.setValue(QLatin1String(kDialectKey), protocol::dialectName(m_session->profile().dialect));
        break;
    }
    case RotatorSession::State::Disconnected:
        if (m_everConnected && !m_operatorDisconnected)
            showState(tr("lost"), QColor(0xe5, 0x48, 0x48), detail);
        else if (!m_operatorDisconnected && !detail.isEmpty())
            showState(tr("failed"), QColor(0xe5, 0x48, 0x48), detail);
        else
            showState(tr("disconnected"), QColor(0x70, 0x70, 0x70), detail);
        m_version->clear();
        break;
    }
}

} // namespace slew::ui

#pragma once
// Where the rotator is and whether we are talking to it: serial port and
// baud, TCP host:port, the built-in simulator or any link URI; the dialect;
// connect/disconnect; a state light; the device's version. The last
// connection that worked is remembered in QSettings.

#include "protocol/dialect.h"
#include "session/rotatorsession.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QStackedWidget;

namespace slew::ui {

class ConnectionBar : public QWidget {
    Q_OBJECT
public:
    explicit ConnectionBar(session::RotatorSession *session, QWidget *parent = nullptr);

    // The URI the fields describe ("serial:/dev/ttyUSB0?baud=19200").
    QString uri() const;
    // Fills the fields from a URI (the best-fitting kind; anything else goes
    // into the free URI field).
    void setUri(const QString &uri);
    protocol::Dialect dialect() const;
    void setDialect(protocol::Dialect d);

    // What the last successful connection was; empty when there was none.
    static QString rememberedUri();
    static std::optional<protocol::Dialect> rememberedDialect();

public slots:
    void connectToRotator(); // with what the fields say
    void disconnectFromRotator();

signals:
    void disconnectRequested(); // the operator is about to disconnect: not a loss

private:
    void onStateChanged(session::RotatorSession::State state, const QString &detail);
    void refreshSerialPorts();
    void showState(const QString &text, const QColor &colour, const QString &detail);

    session::RotatorSession *m_session;
    QComboBox *m_kind;
    QStackedWidget *m_fields;
    QLineEdit *m_simUri;
    QComboBox *m_serialPort;
    QComboBox *m_baud;
    QLineEdit *m_tcpHost;
    QSpinBox *m_tcpPort;
    QLineEdit *m_customUri;
    QComboBox *m_dialect;
    QPushButton *m_connect;
    QLabel *m_light;
    QLabel *m_state;
    QLabel *m_version;
    bool m_operatorDisconnected = true;
    bool m_everConnected = false;
};

} // namespace slew::ui

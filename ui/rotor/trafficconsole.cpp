#include "rotor/trafficconsole.h"

#include "protocol/dialect.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollBar>

namespace slew::ui {

using session::RotatorSession;

TrafficConsole::TrafficConsole(RotatorSession *session, QWidget *parent) : QWidget(parent), m_session(session)
{
    setObjectName(QStringLiteral("trafficConsole"));
    m_view = new QPlainTextEdit;
    m_view->setObjectName(QStringLiteral("trafficView"));
    m_view->setReadOnly(true);
    m_view->setMaximumBlockCount(kMaxEntries);
    m_view->setLineWrapMode(QPlainTextEdit::NoWrap);
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    m_view->setFont(mono);

    m_filter = new QLineEdit;
    m_filter->setObjectName(QStringLiteral("trafficFilter"));
    m_filter->setPlaceholderText(tr("filter, e.g. ^(AZ|EL|GS)"));
    // Its example whole, however narrow the window: the page scrolls instead.
    m_filter->setMinimumWidth(m_filter->fontMetrics().horizontalAdvance(m_filter->placeholderText()) + 40);
    m_filter->setToolTip(tr("Show only the lines that match this regular expression"));
    m_filter->setClearButtonEnabled(true);
    m_invert = new QCheckBox(tr("Hide matches"));
    m_invert->setObjectName(QStringLiteral("trafficInvert"));
    m_showSent = new QCheckBox(tr("Sent"));
    m_showSent->setObjectName(QStringLiteral("trafficShowSent"));
    m_showSent->setChecked(true);
    m_showReceived = new QCheckBox(tr("Received"));
    m_showReceived->setObjectName(QStringLiteral("trafficShowReceived"));
    m_showReceived->setChecked(true);
    auto *clearButton = new QPushButton(tr("Clear"));
    clearButton->setObjectName(QStringLiteral("trafficClear"));

    m_raw = new QLineEdit;
    m_raw->setObjectName(QStringLiteral("rawCommand"));
    m_raw->setFont(mono);
    m_send = new QPushButton(tr("Send"));
    m_send->setObjectName(QStringLiteral("rawSend"));
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("rawMessage"));
    for (QPushButton *b : {clearButton, m_send})
        b->setAutoDefault(false);

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(4, 4, 4, 4);
    grid->addWidget(m_filter, 0, 0);
    grid->addWidget(m_invert, 0, 1);
    grid->addWidget(m_showSent, 0, 2);
    grid->addWidget(m_showReceived, 0, 3);
    grid->addWidget(clearButton, 0, 4);
    grid->addWidget(m_view, 1, 0, 1, 5);
    grid->addWidget(m_raw, 2, 0, 1, 4);
    grid->addWidget(m_send, 2, 4);
    grid->addWidget(m_message, 3, 0, 1, 5);

    m_flush.setInterval(150);
    connect(&m_flush, &QTimer::timeout, this, &TrafficConsole::flushPending);
    m_flush.start();
    connect(session, &RotatorSession::bytesSent, this, [this](const QByteArray &bytes) { add(true, bytes); });
    connect(session, &RotatorSession::bytesReceived, this, &TrafficConsole::onReceived);
    for (QCheckBox *c : {m_invert, m_showSent, m_showReceived})
        connect(c, &QCheckBox::toggled, this, &TrafficConsole::refilter);
    connect(m_filter, &QLineEdit::textChanged, this, &TrafficConsole::refilter);
    connect(clearButton, &QPushButton::clicked, this, &TrafficConsole::clear);
    connect(m_send, &QPushButton::clicked, this, [this] { sendRaw(m_raw->text()); });
    connect(m_raw, &QLineEdit::returnPressed, this, [this] { sendRaw(m_raw->text()); });
    connect(session, &RotatorSession::profileChanged, this, &TrafficConsole::followDialect);
    followDialect();
}

void TrafficConsole::followDialect()
{
    // A SPID frame carries binary resolution bytes, so no printable line is
    // one, and a stray line could only upset the controller's framing.
    const protocol::Dialect d = m_session->profile().dialect;
    const bool binary = protocol::isSpid(d);
    m_raw->setEnabled(!binary);
    m_send->setEnabled(!binary);
    m_raw->setPlaceholderText(binary ? tr("%1 speaks binary frames: raw lines cannot be sent")
                                           .arg(protocol::dialectName(d))
                                     : tr("raw command, e.g. VE or CR1"));
}

QString TrafficConsole::render(const Entry &e)
{
    QString text;
    for (char c : e.line) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n')
            continue; // every line ends in one; showing it adds nothing
        if (c == '\r')
            text += QStringLiteral("\\r");
        else if (u < 0x20 || u > 0x7e)
            text += QStringLiteral("\\x%1").arg(u, 2, 16, QLatin1Char('0'));
        else
            text += QLatin1Char(c);
    }
    return QStringLiteral("%1 %2 %3")
        .arg(QDateTime::fromMSecsSinceEpoch(e.timeMs).toString(QStringLiteral("HH:mm:ss.zzz")),
             e.sent ? QStringLiteral("→") : QStringLiteral("←"), text);
}

void TrafficConsole::add(bool sent, const QByteArray &line)
{
    Entry e{QDateTime::currentMSecsSinceEpoch(), sent, line};
    if (!sent && m_partialTime)
        e.timeMs = m_partialTime; // a line's time is when its first byte came
    m_entries.push_back(e);
    while (m_entries.size() > size_t(kMaxEntries))
        m_entries.pop_front();
    m_pending.push_back(e);
    while (m_pending.size() > size_t(kMaxEntries))
        m_pending.pop_front();
}

void TrafficConsole::onReceived(const QByteArray &bytes)
{
    // Bytes come in arbitrary chunks; show them a line at a time.
    for (char c : bytes) {
        if (m_partial.isEmpty())
            m_partialTime = QDateTime::currentMSecsSinceEpoch();
        m_partial.append(c);
        if (c == '\n' || c == '\r' || m_partial.size() >= kMaxPartialLine) {
            if (m_partial != "\n" && m_partial != "\r")
                add(false, m_partial);
            m_partial.clear();
            m_partialTime = 0;
        }
    }
}

bool TrafficConsole::matches(const Entry &e) const
{
    if (e.sent ? !m_showSent->isChecked() : !m_showReceived->isChecked())
        return false;
    const QString pattern = m_filter->text();
    if (pattern.isEmpty())
        return true;
    const QString line = QString::fromLatin1(e.line).trimmed();
    const bool hit =
        m_pattern.isValid() ? m_pattern.match(line).hasMatch() : line.contains(pattern, Qt::CaseInsensitive);
    return hit != m_invert->isChecked();
}

void TrafficConsole::flushPending()
{
    if (m_pending.empty())
        return;
    QScrollBar *bar = m_view->verticalScrollBar();
    const bool atBottom = bar->value() >= bar->maximum() - 2;
    QStringList lines;
    for (const Entry &e : m_pending) {
        if (matches(e))
            lines << render(e);
    }
    m_pending.clear();
    if (!lines.isEmpty())
        m_view->appendPlainText(lines.join(QLatin1Char('\n')));
    if (atBottom)
        bar->setValue(bar->maximum()); // follow the traffic unless the operator scrolled back
}

void TrafficConsole::refilter()
{
    m_pattern = QRegularExpression(m_filter->text(), QRegularExpression::CaseInsensitiveOption);
    m_pending.clear();
    QStringList lines;
    for (const Entry &e : m_entries) {
        if (matches(e))
            lines << render(e);
    }
    m_view->setPlainText(lines.join(QLatin1Char('\n')));
    m_view->verticalScrollBar()->setValue(m_view->verticalScrollBar()->maximum());
    const bool badPattern = !m_filter->text().isEmpty() && !m_pattern.isValid();
    m_filter->setToolTip(badPattern ? tr("Not a regular expression: matching the text as typed") : QString());
}

bool TrafficConsole::sendRaw(const QString &line)
{
    const session::CommandResult sent = m_session->sendRaw(line);
    if (sent) {
        m_raw->clear();
        m_message->setText(tr("Sent."));
    } else {
        m_message->setText(tr("Not sent: %1").arg(sent.refusal));
    }
    return bool(sent);
}

void TrafficConsole::clear()
{
    m_entries.clear();
    m_pending.clear();
    m_view->clear();
}

} // namespace slew::ui

#include "sharedline.h"

#include "sharedlinelink.h"

#include <QTimer>
#include <QUrl>
#include <QUrlQuery>

namespace slew::transport {

QString SharedLine::lineUri(const QString &uri)
{
    QUrl url(uri.trimmed());
    QUrlQuery query(url);
    if (!query.hasQueryItem(QStringLiteral("rotor")))
        return uri.trimmed();
    query.removeAllQueryItems(QStringLiteral("rotor"));
    url.setQuery(query.isEmpty() ? QString() : query.query());
    QString text = url.toString();
    // `sim:` with an empty query keeps a bare `sim:`.
    if (text.endsWith(u'?'))
        text.chop(1);
    return text;
}

QString SharedLine::rotorUri(const QString &lineUri, int rotor)
{
    const QString line = SharedLine::lineUri(lineUri);
    return line + (line.contains(u'?') ? u'&' : u'?') + QStringLiteral("rotor=%1").arg(rotor);
}

SharedLine::SharedLine(const QString &uri, QObject *parent) : QObject(parent), m_uri(lineUri(uri))
{
    LinkResult made = createLink(m_uri);
    if (!made.link) {
        m_error = made.error;
        return;
    }
    m_line = std::move(made.link);
    connect(m_line.get(), &Link::opened, this, &SharedLine::onOpened);
    connect(m_line.get(), &Link::failed, this, [this](const QString &reason) { onDown(reason, true); });
    connect(m_line.get(), &Link::lost, this, [this](const QString &reason) { onDown(reason, false); });
    connect(m_line->device(), &QIODevice::readyRead, this, &SharedLine::onReadyRead);
}

SharedLine::~SharedLine()
{
    const QList<SharedLineLink *> rotors = m_rotors;
    m_rotors.clear();
    m_opening.clear();
    m_open.clear();
    for (SharedLineLink *rotor : rotors)
        rotor->lineGone();
    if (m_line)
        m_line->close();
}

LinkResult SharedLine::makeLink(const QString &uri)
{
    if (!m_line)
        return {nullptr, m_error};
    if (lineUri(uri) != m_uri)
        return {nullptr, tr("%1 is not on the shared line %2").arg(uri, m_uri)};
    // On a shared line every rotor is named: "the controller's default
    // rotor" changes whenever another rotor is sent a go-to.
    int rotor = 1;
    const QUrlQuery query{QUrl(uri.trimmed())};
    if (query.hasQueryItem(QStringLiteral("rotor"))) {
        bool ok = false;
        rotor = query.queryItemValue(QStringLiteral("rotor")).toInt(&ok);
        if (!ok || rotor < 1 || rotor > 4)
            return {nullptr, tr("%1: rotor must be 1 to 4").arg(uri)};
    }
    auto link = std::make_unique<SharedLineLink>(uri.trimmed(), rotor, this);
    m_rotors.append(link.get());
    return {std::move(link), {}};
}

void SharedLine::openFor(SharedLineLink *rotor)
{
    if (m_open.contains(rotor) || m_opening.contains(rotor))
        return;
    if (m_line->isOpen()) {
        m_open.append(rotor);
        // As any link: opened() comes after open() has returned.
        QPointer<SharedLineLink> guard(rotor);
        QTimer::singleShot(0, this, [this, guard] {
            if (guard && m_open.contains(guard.data()))
                guard->lineOpened();
        });
        return;
    }
    const bool alreadyOpening = !m_opening.isEmpty();
    m_opening.append(rotor);
    if (!alreadyOpening)
        m_line->open();
}

void SharedLine::closeFor(SharedLineLink *rotor)
{
    m_opening.removeAll(rotor);
    m_open.removeAll(rotor);
    if (m_lastWriter == rotor)
        m_lastWriter = nullptr;
    queryDone(rotor);
    if (m_opening.isEmpty() && m_open.isEmpty() && m_line && m_line->isOpen())
        m_line->close();
}

void SharedLine::forget(SharedLineLink *rotor)
{
    closeFor(rotor);
    m_rotors.removeAll(rotor);
    // The last link gone while the line was still opening: stop opening it.
    if (m_opening.isEmpty() && m_open.isEmpty() && m_line)
        m_line->close();
}

void SharedLine::onOpened()
{
    const QList<SharedLineLink *> opening = m_opening;
    m_opening.clear();
    if (opening.isEmpty()) {
        m_line->close(); // every rotor gave up while it opened
        return;
    }
    m_open.append(opening);
    for (SharedLineLink *rotor : opening) {
        if (m_open.contains(rotor)) // an earlier one's handler may have closed it
            rotor->lineOpened();
    }
}

void SharedLine::onDown(const QString &reason, bool opening)
{
    const QList<SharedLineLink *> told = opening ? m_opening : m_open;
    m_opening.clear();
    m_open.clear();
    m_holder = nullptr;
    m_lastWriter = nullptr;
    m_waiting.clear();
    m_line->close();
    // Each rotor's session decides for itself whether and when to reopen.
    for (SharedLineLink *rotor : told) {
        if (m_rotors.contains(rotor))
            rotor->lineDown(reason, opening);
    }
}

void SharedLine::writeToLine(SharedLineLink *rotor, const QByteArray &bytes)
{
    m_lastWriter = rotor;
    m_line->device()->write(bytes);
}

void SharedLine::sendCommand(SharedLineLink *rotor, const QByteArray &bytes)
{
    if (!m_open.contains(rotor))
        return;
    writeToLine(rotor, bytes);
}

void SharedLine::sendQuery(SharedLineLink *rotor, const QByteArray &bytes)
{
    if (!m_open.contains(rotor))
        return;
    if (m_holder == nullptr || m_holder == rotor) {
        m_holder = rotor; // a resend of its own unanswered query keeps the wire
        writeToLine(rotor, bytes);
        return;
    }
    // One query per rotor: a resend while still waiting replaces the first.
    for (WaitingQuery &w : m_waiting) {
        if (w.rotor == rotor) {
            w.bytes = bytes;
            return;
        }
    }
    m_waiting.append({rotor, bytes});
}

void SharedLine::queryDone(SharedLineLink *rotor)
{
    m_waiting.removeIf([rotor](const WaitingQuery &w) { return w.rotor == rotor; });
    if (m_holder == rotor)
        releaseWire();
}

void SharedLine::releaseWire()
{
    m_holder = nullptr;
    if (m_waiting.isEmpty())
        return;
    const WaitingQuery next = m_waiting.takeFirst();
    m_holder = next.rotor;
    writeToLine(next.rotor, next.bytes);
}

void SharedLine::onReadyRead()
{
    const QByteArray bytes = m_line->device()->readAll();
    SharedLineLink *to = m_holder ? m_holder : m_lastWriter;
    if (!to || !to->deliver(bytes))
        m_bytesDropped += bytes.size();
}

} // namespace slew::transport

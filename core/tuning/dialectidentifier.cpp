#include "dialectidentifier.h"

#include "session/rotatorsession.h"

#include <QRegularExpression>
#include <QStringList>
#include <QUrl>
#include <QUrlQuery>

namespace slew::tuning {

using protocol::Dialect;
using session::Capabilities;
using session::RotatorSession;

QString DialectResult::describe() const
{
    QStringList answered;
    const Capabilities &c = capabilities;
    if (c.positionFeedback)
        answered << QObject::tr("position");
    if (c.version)
        answered << QStringLiteral("VE");
    if (c.status)
        answered << QStringLiteral("GS");
    if (c.errors)
        answered << QStringLiteral("GE");
    if (c.inputs)
        answered << QStringLiteral("IP");
    if (c.config)
        answered << QStringLiteral("CR/CW");
    if (c.encoders)
        answered << QStringLiteral("\\?ENC");
    if (c.velocity)
        answered << QObject::tr("velocity (VL/VR/VU/VD)");
    QString text = QStringLiteral("%1: %2").arg(protocol::dialectName(dialect),
                                                answered.isEmpty() ? QObject::tr("no answer") : answered.join(QStringLiteral(", ")));
    // An MD-01/02 in ROT2 mode answers a status exactly as a Rot2Prog does;
    // only a set (which it answers) or its move command tells them apart,
    // and neither is a question to put to a rotator unasked.
    if (dialect == protocol::Dialect::Rot2Prog && c.positionFeedback)
        text += QObject::tr(" (SPID frames; an MD-01/02 answers the same: choose md01 for its move command)");
    if (firmware != protocol::Firmware::Generic)
        text += QObject::tr(" (%1)").arg(protocol::firmwareTitle(firmware));
    return text;
}

DialectIdentifier::DialectIdentifier(QObject *parent)
    : QObject(parent), m_attempt(this, 8000, [this] { conclude(Capabilities{}); })
{
}

DialectIdentifier::~DialectIdentifier() = default;

bool DialectIdentifier::start(const QString &uri)
{
    m_error.clear();
    if (uri.trimmed().isEmpty()) {
        m_error = tr("no link to identify");
        return false;
    }
    cancel();
    m_uri = uri.trimmed();
    m_results.clear();
    m_pending = {Dialect::Easycomm3, Dialect::SatNogs, Dialect::Easycomm2, Dialect::Gs232B, Dialect::Micro2g};
    // SPID's binary status frame last: it is only worth its wait once no
    // line protocol got a position. First, on a line at a SPID
    // controller's own rate (Rot2Prog 600 baud, Rot1Prog 1200).
    const QList<Dialect> spid{Dialect::Rot2Prog, Dialect::Rot1Prog};
    const int baud = QUrlQuery(QUrl(m_uri)).queryItemValue(QStringLiteral("baud")).toInt();
    m_pending = baud == 600 || baud == 1200 ? spid + m_pending : m_pending + spid;
    m_total = int(m_pending.size());
    next();
    return true;
}

void DialectIdentifier::cancel()
{
    m_pending.clear();
    m_attempt.end();
}

std::optional<DialectResult> DialectIdentifier::best() const
{
    std::optional<DialectResult> winner;
    for (const DialectResult &r : m_results) {
        if (r.capabilities.positionFeedback && (!winner || r.score > winner->score))
            winner = r;
    }
    return winner;
}

void DialectIdentifier::next()
{
    if (m_pending.isEmpty()) {
        emit progress(100, tr("done"));
        emit finished(best().has_value());
        return;
    }
    const Dialect d = m_pending.takeFirst();
    // A controller that answered an Easycomm position is no GS-232, no Micro-2g and no
    // SPID controller (nor one that answered SPID frames anything else):
    // asking would only wait out its silence. The Easycomm flavours are all
    // asked, since they differ in how much they answer.
    if (best() && (d == Dialect::Gs232B || d == Dialect::Micro2g || protocol::isSpid(d) || protocol::isSpid(best()->dialect))) {
        next();
        return;
    }
    emit progress(100 * int(m_results.size()) / m_total, tr("asking in %1").arg(protocol::dialectName(d)));
    DialectResult r;
    r.dialect = d;
    m_results.append(r);
    RotatorSession *session = m_attempt.begin(d);
    connect(session, &RotatorSession::capabilitiesChanged, this, [this](const Capabilities &caps) {
        if (caps.probed)
            conclude(caps);
    });
    // The probe asks for the position first. A dialect that gets none cannot
    // win (best() needs a position), so once the session moves on to its next
    // question without one, the rest of its questions are not worth the wait:
    // a Micro-2g asked in Easycomm would leave each of them to time out.
    connect(session, &RotatorSession::bytesSent, this, [this, session, first = QByteArray()](const QByteArray &bytes) mutable {
        if (first.isEmpty())
            first = bytes;
        else if (bytes != first && !session->hasPosition())
            conclude(Capabilities{});
    });
    // K3NG's GS-232B emulation runs its two reports together
    // (`AZ=059EL=025`), where a Yaesu puts spaces between them: the one
    // thing that tells them apart on the wire.
    m_joinedGs232Report = false;
    if (d == Dialect::Gs232B) {
        connect(session, &RotatorSession::bytesReceived, this, [this, heard = QByteArray()](const QByteArray &bytes) mutable {
            heard = (heard + bytes).right(64);
            static const QRegularExpression joined(QStringLiteral("AZ=\\d+(\\.\\d+)?EL="));
            m_joinedGs232Report = m_joinedGs232Report || joined.match(QString::fromLatin1(heard)).hasMatch();
        });
    }
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s, const QString &why) {
        if (s == RotatorSession::State::Disconnected) {
            m_error = why;
            conclude(Capabilities{});
        }
    });
    m_attempt.go(m_uri);
}

void DialectIdentifier::conclude(const Capabilities &caps)
{
    if (!m_attempt.isRunning() || m_results.isEmpty())
        return;
    DialectResult &r = m_results.back();
    r.capabilities = caps;
    r.version = m_attempt.session()->version();
    // Each answer counts for the dialect and each query it left unanswered
    // against it: a richer dialect than the device speaks asks for more
    // than it gets, so the dialect that explains everything wins.
    using protocol::Op;
    const std::pair<Op, bool> asked[] = {
        {Op::Azimuth, caps.positionFeedback}, {Op::Version, caps.version}, {Op::Status, caps.status},
        {Op::ErrorFlags, caps.errors},         {Op::ReadInput, caps.inputs}, {Op::ConfigRead, caps.config},
        {Op::Encoders, caps.encoders},
    };
    r.score = 0;
    for (const auto &[op, answered] : asked) {
        if (protocol::dialectSupports(r.dialect, op))
            r.score += answered ? 1 : -1;
    }
    // SatNOGS firmware names itself at the front of VE.
    if (r.dialect == Dialect::SatNogs && r.version.startsWith(QLatin1String("SatNOGS"), Qt::CaseInsensitive))
        r.score += 1;
    // So does the Micro-2g program, in its `?` line (docs/protocol.md).
    if (r.dialect == Dialect::Micro2g && r.version.startsWith(QLatin1String("Micro-2g"), Qt::CaseInsensitive))
        r.score += 1;
    // K3NG's Easycom says `?` to every query it lacks; a plain Easycomm II
    // controller leaves them unanswered.
    r.firmware = protocol::firmwareOf(r.dialect, protocol::Firmware::Generic);
    if (r.dialect == Dialect::Easycomm2 && caps.positionFeedback && m_attempt.session()->refusedRequests() > 0)
        r.firmware = protocol::Firmware::K3ng;
    if (r.dialect == Dialect::Gs232B && caps.positionFeedback && m_joinedGs232Report)
        r.firmware = protocol::Firmware::K3ng;
    m_attempt.end();
    QMetaObject::invokeMethod(this, &DialectIdentifier::next, Qt::QueuedConnection);
}

} // namespace slew::tuning

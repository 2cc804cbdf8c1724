#include "rotor/gotopanel.h"

#include "operatortheme.h"
#include "operatoractions.h"

#include "model/movegate.h"

#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <cmath>

namespace slew::ui {

namespace {

std::optional<double> parseAngle(const QString &text)
{
    QString t = text.trimmed();
    t.replace(QLatin1Char(','), QLatin1Char('.'));
    if (t.endsWith(QChar(0x00b0)))
        t.chop(1);
    bool ok = false;
    const double v = t.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

void markField(QLineEdit *field, bool bad)
{
    field->setStyleSheet(bad ? refusedField() : QString());
}

} // namespace

GotoPanel::GotoPanel(face::StationFace *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("gotoPanel"));
    m_az = new QLineEdit;
    m_az->setObjectName(QStringLiteral("gotoAzimuth"));
    m_az->setPlaceholderText(tr("degrees"));
    m_el = new QLineEdit;
    m_el->setObjectName(QStringLiteral("gotoElevation"));
    m_el->setPlaceholderText(tr("degrees"));
    m_go = new QPushButton(tr("Go"));
    m_go->setObjectName(QStringLiteral("gotoButton"));
    m_go->setAutoDefault(false);
    m_go->setToolTip(tr("Move to this position (Enter)"));
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("gotoMessage"));
    m_message->setWordWrap(true);

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Az")), 0, 0);
    grid->addWidget(m_az, 0, 1);
    grid->addWidget(new QLabel(tr("El")), 0, 2);
    grid->addWidget(m_el, 0, 3);
    grid->addWidget(m_go, 0, 4);
    grid->addWidget(m_message, 1, 0, 1, 5);

    connect(m_az, &QLineEdit::textChanged, this, &GotoPanel::revalidate);
    connect(m_el, &QLineEdit::textChanged, this, &GotoPanel::revalidate);
    // A refused go-to leaves the focus in the field, to be put right there.
    for (QLineEdit *field : {m_az, m_el}) {
        connect(field, &QLineEdit::returnPressed, this, [this] {
            if (go())
                emit sentByEnter();
        });
    }
    connect(m_go, &QPushButton::clicked, this, &GotoPanel::go);
    connect(station, &face::StationFace::stateChanged, this, [this](const face::StationState &s) {
        if (s.azimuthOnly != m_azimuthOnly)
            followAxes();
        else
            revalidate();
    });
    connect(station, &face::StationFace::liveChanged, this, &GotoPanel::revalidate);
    connect(station, &face::StationFace::answered, this, [this](const QString &id, const face::Outcome &outcome) {
        if (id != m_awaiting)
            return;
        m_awaiting.clear();
        if (outcome.isRefused())
            showRefusal(outcome.reason());
    });
    followAxes();
}

void GotoPanel::showRefusal(const QString &why)
{
    m_message->setText(why);
    m_message->setStyleSheet(refusedText());
}

void GotoPanel::followAxes()
{
    // An azimuth-only rotator: elevation is 0 and not the operator's to set.
    const std::optional<face::StationState> state = m_station->state();
    const bool azimuthOnly = m_azimuthOnly = state && state->azimuthOnly;
    if (azimuthOnly)
        m_el->setText(QStringLiteral("0"));
    m_el->setEnabled(!azimuthOnly);
    m_el->setToolTip(azimuthOnly ? tr("This rotator turns azimuth only.") : QString());
    revalidate();
}

GotoPanel::Checked GotoPanel::check() const
{
    Checked c;
    const auto az = parseAngle(m_az->text());
    const auto el = parseAngle(m_el->text());
    if (m_az->text().trimmed().isEmpty() || m_el->text().trimmed().isEmpty()) {
        c.message = tr("Enter azimuth and elevation.");
        return c;
    }
    if (!az || !el) {
        c.azimuthBad = !az;
        c.elevationBad = !el;
        c.message = !az ? tr("Azimuth is not a number.") : tr("Elevation is not a number.");
        return c;
    }
    // The station's gate, as it will decide when Go is pressed.
    const model::MoveCheck check = m_station->previewPointing(*az, *el);
    if (!check.allowed()) {
        const std::optional<face::StationState> state = m_station->state();
        c.elevationBad = state && !model::MoveGate(state->limits).elevation(*el).allowed();
        c.azimuthBad = !c.elevationBad;
        c.message = check.refusal;
        return c;
    }
    c.azimuth = check.azimuth;
    c.elevation = el;
    if (std::abs(check.azimuth - *az) > 1e-9)
        c.message = tr("Will turn to %1° (the shorter way through the overlap).").arg(check.azimuth, 0, 'f', 1);
    return c;
}

void GotoPanel::revalidate()
{
    const Checked c = check();
    const bool filled = !m_az->text().trimmed().isEmpty() && !m_el->text().trimmed().isEmpty();
    const bool ok = c.azimuth && c.elevation;
    markField(m_az, c.azimuthBad);
    markField(m_el, c.elevationBad);
    m_message->setText(filled ? c.message : QString());
    m_message->setStyleSheet(ok ? QString() : refusedText());
    const std::optional<face::StationState> state = m_station->state();
    m_go->setEnabled(ok && m_station->isLive() && state && state->link == u"connected");
}

void GotoPanel::setFields(double az, double el)
{
    m_az->setText(QString::number(az, 'f', 1));
    m_el->setText(QString::number(el, 'f', 1));
}

bool GotoPanel::go()
{
    const Checked c = check();
    if (!c.azimuth || !c.elevation) {
        m_message->setText(c.message);
        m_message->setStyleSheet(refusedText());
        return false; // nothing is sent
    }
    // The bearing as typed: the gate decides again at sending time, from
    // where the rotator is then, as the preview did from where it was.
    const face::Outcome sent = m_station->gotoPosition(*parseAngle(m_az->text()), *c.elevation);
    if (sent.isRefused()) {
        showRefusal(sent.reason());
        return false;
    }
    m_awaiting = sent.id();
    // Where it goes: the station's target once it has one, else the
    // position its gate previewed.
    const std::optional<face::StationState> state = m_station->state();
    const QPointF target = sent.isDone() && state && state->target ? *state->target : QPointF(*c.azimuth, *c.elevation);
    emit moveSent(tr("go to %1").arg(describePosition(target)), target);
    return true;
}

} // namespace slew::ui

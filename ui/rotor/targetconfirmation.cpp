#include "rotor/targetconfirmation.h"

#include "operatortheme.h"
#include <QCheckBox>
#include <QHBoxLayout>
#include <QVBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>

namespace slew::ui {

namespace {
const char *kAskKey = "plot/confirmTarget";
}

TargetConfirmation::TargetConfirmation(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("targetConfirmation"));
    m_question = new QLabel(tr("Click the plot to pick a target."));
    m_question->setObjectName(QStringLiteral("targetQuestion"));
    m_go = new QPushButton(tr("Go"));
    m_go->setObjectName(QStringLiteral("targetGo"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setObjectName(QStringLiteral("targetCancel"));
    m_ask = new QCheckBox(tr("Ask before moving"));
    m_ask->setObjectName(QStringLiteral("targetAsk"));
    m_ask->setChecked(QSettings().value(QLatin1String(kAskKey), true).toBool());
    for (QPushButton *b : {m_go, m_cancel}) {
        b->setAutoDefault(false);
        b->setFocusPolicy(Qt::NoFocus);
    }
    // The question on a line of its own, two lines high whatever it says, and
    // taking no width of its own: a longer text never widens the plot's
    // column, so the plot never moves under the pointer that clicked it.
    m_question->setWordWrap(true);
    m_question->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_question->setFixedHeight(2 * m_question->fontMetrics().lineSpacing() + 2);
    m_question->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_go);
    buttons->addWidget(m_cancel);
    buttons->addStretch(1);
    buttons->addWidget(m_ask);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_question);
    layout->addLayout(buttons);
    connect(m_go, &QPushButton::clicked, this, &TargetConfirmation::accept);
    connect(m_cancel, &QPushButton::clicked, this, &TargetConfirmation::cancel);
    connect(m_ask, &QCheckBox::toggled, this,
            [](bool on) { QSettings().setValue(QLatin1String(kAskKey), on); });
    setPending(std::nullopt);
}

bool TargetConfirmation::confirmationWanted() const
{
    return m_ask->isChecked();
}

void TargetConfirmation::setConfirmationWanted(bool on)
{
    m_ask->setChecked(on);
}

void TargetConfirmation::setPending(std::optional<QPointF> azEl)
{
    m_pending = azEl;
    m_go->setEnabled(azEl.has_value());
    m_cancel->setEnabled(azEl.has_value());
    emit pendingChanged(azEl);
}

void TargetConfirmation::ask(double az, double el, const QString &what)
{
    m_question->setStyleSheet(QString());
    const QString point = tr("az %1°, el %2°").arg(az, 0, 'f', 1).arg(el, 0, 'f', 1);
    m_question->setText(what.isEmpty() ? tr("Go to %1?").arg(point) : tr("Go to %1, %2?").arg(what, point));
    m_going = false;
    m_question->setToolTip(QString());
    setPending(QPointF(az, el));
}

void TargetConfirmation::showProblem(const QString &text)
{
    m_question->setStyleSheet(refusedText());
    m_question->setText(text);
    m_question->setToolTip(text);
    m_going = false;
    setPending(std::nullopt);
}

void TargetConfirmation::accept()
{
    if (!m_pending)
        return;
    const QPointF p = *m_pending;
    setPending(std::nullopt);
    // The window sends it, then says showGoing() or showProblem().
    emit accepted(p.x(), p.y());
}

void TargetConfirmation::showGoing(double az, double el)
{
    m_question->setStyleSheet(QString());
    m_question->setText(tr("Going to az %1°, el %2°.").arg(az, 0, 'f', 1).arg(el, 0, 'f', 1));
    m_question->setToolTip(QString());
    m_going = true;
}

void TargetConfirmation::moveEnded()
{
    if (m_going)
        cancel();
}

void TargetConfirmation::cancel()
{
    m_going = false;
    m_question->setStyleSheet(QString());
    m_question->setText(tr("Click the plot to pick a target."));
    setPending(std::nullopt);
}

} // namespace slew::ui

// SPDX-License-Identifier: GPL-3.0-or-later
#include "wizard/tuningpage.h"

#include "wizard/pagebody.h"
#include "protocol/dialect.h"
#include "session/rotatorsession.h"
#include "wizard/setupwizard.h"
#include "wizard/tuningchart.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

using session::Axis;
using tuning::AxisTuner;

namespace {
constexpr int kFigureLines = 7; // title, four figures, the gains, and a spare for a wrapped line
}

TuningPage::TuningPage(SetupWizard *wizard)
    : QWizardPage(wizard), m_wizard(wizard), m_tuner(wizard->session()), m_motionRun(wizard->session())
{
    setTitle(tr("Tuning"));
    setSubTitle(tr("Each axis makes a small step with its present gains; Slew fits a model to it, proposes "
                   "gains that damp it, tries them and shows both runs. Nothing stays unless you accept."));
    m_axis = new QComboBox(this);
    m_axis->setObjectName(QStringLiteral("axis"));
    m_axis->addItem(tr("Azimuth"), int(Axis::Azimuth));
    m_axis->addItem(tr("Elevation"), int(Axis::Elevation));
    m_tune = new QPushButton(tr("Tune"), this);
    m_tune->setObjectName(QStringLiteral("tune"));
    m_measureSpeed = new QPushButton(tr("Measure speed"), this);
    m_measureSpeed->setObjectName(QStringLiteral("measureSpeed"));
    m_measureSpeed->setToolTip(tr("Moves the axis %1° and records its speed, acceleration and response delay: "
                                  "what the tracker plans passes with.").arg(tuning::kMotionStepDeg, 0, 'f', 0));
    m_progress = new QProgressBar(this);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("tuningStatus"));
    m_status->setWordWrap(true);
    m_chart = new TuningChart(this);
    m_chart->setObjectName(QStringLiteral("tuningChart"));
    m_before = new QLabel(this);
    m_before->setObjectName(QStringLiteral("beforeFigures"));
    m_after = new QLabel(this);
    m_after->setObjectName(QStringLiteral("afterFigures"));
    // The figures arrive after a run; their room is kept from the start, so
    // the page's minimum size (which the wizard's follows) already holds
    // them and they never land on the chart.
    for (QLabel *figures : {m_before, m_after}) {
        figures->setTextFormat(Qt::RichText);
        figures->setAlignment(Qt::AlignLeft | Qt::AlignTop);
        figures->setMinimumHeight(figures->fontMetrics().lineSpacing() * kFigureLines);
        figures->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    }
    m_accept = new QPushButton(tr("Accept new gains"), this);
    m_accept->setObjectName(QStringLiteral("accept"));
    m_retry = new QPushButton(tr("Retry"), this);
    m_retry->setObjectName(QStringLiteral("retry"));
    m_keepOld = new QPushButton(tr("Keep old gains"), this);
    m_keepOld->setObjectName(QStringLiteral("keepOld"));
    setDeciding(false);

    auto *top = new QHBoxLayout;
    top->addWidget(m_axis);
    top->addWidget(m_tune);
    top->addWidget(m_measureSpeed);
    auto *figuresRow = new QHBoxLayout;
    figuresRow->addWidget(m_before);
    figuresRow->addWidget(m_after);
    auto *decide = new QHBoxLayout;
    decide->addWidget(m_accept);
    decide->addWidget(m_retry);
    decide->addWidget(m_keepOld);
    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addLayout(top);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_chart, 1);
    layout->addLayout(figuresRow);
    layout->addLayout(decide);

    connect(m_tune, &QPushButton::clicked, this, &TuningPage::start);
    // m_accept is enabled exactly while a result waits for a decision.
    connect(wizard->session(), &session::RotatorSession::capabilitiesChanged, this,
            [this] { setDeciding(m_accept->isEnabled()); });
    connect(m_measureSpeed, &QPushButton::clicked, this, &TuningPage::measureSpeed);
    connect(&m_motionRun.experiment(), &tuning::StepExperiment::sampleRecorded, m_chart,
            [this](const tuning::PositionSample &sample) { m_chart->addSample(false, sample); });
    connect(&m_motionRun, &tuning::MotionRun::measured, this, [this](Axis axis, const tuning::AxisMotion &m) {
        model::RotatorMotion &motion = m_wizard->profile().motion;
        (axis == Axis::Azimuth ? motion.azSpeedDegS : motion.elSpeedDegS) = m.speedDegS;
        (axis == Axis::Azimuth ? motion.azAccelDegS2 : motion.elAccelDegS2) = m.accelDegS2;
        motion.responseDelayS = m.responseDelayS;
        m_status->setText(tr("%1 turns at %2°/s, gets up to speed at %3°/s² and answers in %4 s; "
                             "the profile keeps it for tracking.")
                              .arg(axis == Axis::Azimuth ? tr("Azimuth") : tr("Elevation"))
                              .arg(m.speedDegS, 0, 'f', 2)
                              .arg(m.accelDegS2, 0, 'f', 1)
                              .arg(m.responseDelayS, 0, 'f', 2));
        setDeciding(false);
    });
    connect(&m_motionRun, &tuning::MotionRun::failed, this, [this](const QString &why) {
        m_status->setText(tr("Speed not measured: %1.").arg(why));
        setDeciding(false);
    });
    connect(m_accept, &QPushButton::clicked, &m_tuner, &AxisTuner::accept);
    connect(m_keepOld, &QPushButton::clicked, &m_tuner, &AxisTuner::keepOldGains);
    connect(m_retry, &QPushButton::clicked, this, [this] {
        setDeciding(false);
        m_chart->clear();
        m_tuner.retry();
    });
    connect(&m_tuner, &AxisTuner::progress, this, [this](int percent, const QString &what) {
        m_progress->setValue(percent);
        m_status->setText(what);
    });
    connect(&m_tuner, &AxisTuner::sampleRecorded, m_chart, &TuningChart::addSample);
    connect(&m_tuner, &AxisTuner::resultReady, this, &TuningPage::showResult);
    connect(&m_tuner, &AxisTuner::finished, this, [this](const tuning::TuningResult &r) {
        model::RotatorProfile &p = m_wizard->profile();
        const model::PidGains kept = r.applied ? r.newGains : r.oldGains;
        (r.axis == Axis::Azimuth ? p.azGains : p.elGains) = kept;
        p.motion = tuning::withMeasuredMotion(p.motion, r); // what the tracker plans with
        setDeciding(false);
        m_status->setText(r.applied ? tr("New %1 gains kept on the controller.").arg(tuning::axisName(r.axis))
                                    : tr("Old %1 gains written back.").arg(tuning::axisName(r.axis)));
        emit completeChanged();
    });
    auto ended = [this](const QString &why) {
        setDeciding(false);
        m_status->setText(why);
        emit completeChanged();
    };
    connect(&m_tuner, &AxisTuner::failed, this, ended);
    connect(&m_tuner, &AxisTuner::cancelled, this, ended);
    connect(wizard, &SetupWizard::stopRequested, &m_tuner, &AxisTuner::cancel);
    // A speed measurement ends silently when cancelled: the page says so
    // and offers its buttons again.
    connect(wizard, &SetupWizard::stopRequested, this, [this] {
        if (!m_motionRun.isRunning())
            return;
        m_motionRun.cancel();
        m_status->setText(tr("Speed measurement stopped."));
        setDeciding(false);
        emit completeChanged();
    });
}

void TuningPage::measureSpeed()
{
    m_chart->clear();
    if (!m_motionRun.start(Axis(m_axis->currentData().toInt()))) {
        m_status->setText(m_motionRun.error());
        return;
    }
    m_status->setText(tr("Measuring: a %1° move.").arg(tuning::kMotionStepDeg, 0, 'f', 0));
    m_tune->setEnabled(false);
    m_measureSpeed->setEnabled(false);
}

void TuningPage::start()
{
    m_chart->clear();
    m_before->clear();
    m_after->clear();
    if (!m_tuner.start(Axis(m_axis->currentData().toInt()))) {
        m_status->setText(m_tuner.error());
        return;
    }
    m_tune->setEnabled(false);
    m_axis->setEnabled(false);
    emit completeChanged();
}

QString TuningPage::figures(const QString &title, const tuning::StepMetrics &m, const model::PidGains &g)
{
    return tr("<b>%1</b><br>rise time %2<br>overshoot %3 %<br>settling time %4<br>steady-state error %5°<br>"
              "kp %6 · ki %7 · kd %8")
        .arg(title, tuning::formatSeconds(m.riseTime, m.rose))
        .arg(m.overshootPercent, 0, 'f', 1)
        .arg(m.settled ? tuning::formatSeconds(m.settlingTime, true) : tr("> %1 s").arg(m.settlingTime, 0, 'f', 1))
        .arg(m.steadyStateError, 0, 'f', 3)
        .arg(g.kp)
        .arg(g.ki)
        .arg(g.kd);
}

void TuningPage::showResult(const tuning::TuningResult &r)
{
    m_chart->showResult(r);
    m_before->setText(figures(tr("Before"), r.beforeMetrics, r.oldGains));
    m_after->setText(figures(tr("After (on trial)"), r.afterMetrics, r.newGains));
    setDeciding(true);
}

void TuningPage::setDeciding(bool deciding)
{
    const bool running = (m_tuner.isRunning() || m_motionRun.isRunning()) && !deciding;
    m_accept->setEnabled(deciding);
    m_retry->setEnabled(deciding);
    m_keepOld->setEnabled(deciding);
    // The gains live in CR/CW registers: without them (SPID) there is
    // nothing to tune, but the speed can still be measured.
    const auto &caps = m_wizard->session()->capabilities();
    const bool noGains = caps.probed && !caps.config;
    m_tune->setEnabled(!running && !deciding && !noGains);
    m_tune->setToolTip(noGains ? tr("%1 has no gain registers, so there are no gains to tune.")
                                     .arg(protocol::dialectName(m_wizard->session()->profile().dialect))
                               : QString());
    m_measureSpeed->setEnabled(!running && !deciding);
    m_axis->setEnabled(!running && !deciding);
}

bool TuningPage::isComplete() const
{
    // Tuning is optional, but not half done: no trial gains left undecided.
    return !m_tuner.isRunning() && !m_motionRun.isRunning();
}

} // namespace slew::ui

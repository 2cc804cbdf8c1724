// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radiopanel.h"

#include "operatortheme.h"
#include "radio/radiocontrol.h"
#include "radio/radiolinkbox.h"
#include "radio/radiopassbandtuner.h"
#include "radio/radioplanform.h"
#include "radio/radioplansettings.h"
#include "radio/radioreadout.h"
#include "radio/radiotransponderdialog.h"
#include "radio/radiovfochoice.h"

#include "radio/frequencytext.h"
#include "radio/transponderset.h"
#include "radio/transpondersources.h"
#include "radio/transponderwatch.h"
#include "sky/elementsetsources.h"
#include "station/dopplerradio.h"
#include "station/station.h"
#include "tracking/passrunner.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

namespace {

QGroupBox *box(const QString &title, QWidget *content, const QString &name)
{
    auto *group = new QGroupBox(title);
    group->setObjectName(name);
    auto *layout = new QVBoxLayout(group);
    // Tight, as the control column's groups: the tab must fit 1280x720.
    layout->setContentsMargins(6, 2, 6, 4);
    layout->addWidget(content);
    return group;
}

QString describePlan(const radio::RadioPlan &plan)
{
    const radio::SatelliteFrequencies &f = plan.frequencies;
    QString text = QObject::tr("downlink %1").arg(radio::groupedMegahertz(f.downlinkHz + f.downlinkOffsetHz));
    if (!plan.receiveMode.isEmpty())
        text += QLatin1Char(' ') + plan.receiveMode;
    if (f.uplinkHz) {
        text += QObject::tr(", uplink %1").arg(radio::groupedMegahertz(*f.uplinkHz + f.uplinkOffsetHz));
        if (!plan.transmitMode.isEmpty())
            text += QLatin1Char(' ') + plan.transmitMode;
    }
    return text;
}

} // namespace

RadioPanel::RadioPanel(station::Station *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("radioPanel"));
    station::DopplerRadio *radio = m_station->radio();
    auto *vfos = new RadioVfoChoice(radio); // before the link box, which may connect at once
    m_link = new RadioLinkBox(radio);
    m_form = new RadioPlanForm;
    m_readout = new RadioReadout(m_station);
    m_apply = new QPushButton(tr("Apply"));
    m_apply->setObjectName(QStringLiteral("radioApply"));
    m_apply->setAutoDefault(false);
    m_apply->setToolTip(tr("Tune the radio to these during the satellite's passes, and keep them for it"));
    m_planState = new QLabel;
    m_planState->setObjectName(QStringLiteral("radioPlanState"));
    m_planState->setWordWrap(true);

    auto *plan = new QWidget;
    auto *planLayout = new QVBoxLayout(plan);
    planLayout->setContentsMargins(0, 0, 0, 0);
    planLayout->setSpacing(4);
    planLayout->addWidget(m_form);
    auto *refresh = new QPushButton(tr("Refresh transponders"));
    refresh->setObjectName(QStringLiteral("radioRefreshTransponders"));
    refresh->setAutoDefault(false);
    refresh->setToolTip(tr("Fetch the transponder lists (SatNOGS DB's, unless others are kept) into the cache "
                           "beside the element sets"));
    connect(refresh, &QPushButton::clicked, this, &RadioPanel::refreshTransponders);
    auto *sources = new QPushButton(tr("Sources…"));
    sources->setObjectName(QStringLiteral("radioTransponderSources"));
    sources->setAutoDefault(false);
    sources->setToolTip(tr("Add or remove transponder sources: Gpredict .trsp files, SatNOGS DB lists, URLs "
                           "(the list slew --update-transponders keeps too)"));
    connect(sources, &QPushButton::clicked, this, &RadioPanel::showTransponderSources);
    auto *applyRow = new QHBoxLayout;
    applyRow->addWidget(m_apply, 0, Qt::AlignTop);
    applyRow->addWidget(refresh, 0, Qt::AlignTop);
    applyRow->addWidget(sources, 0, Qt::AlignTop);
    applyRow->addWidget(m_planState, 1);
    planLayout->addLayout(applyRow);
    // What the last refresh of the transponders gave, on the tab (the
    // Events tab has each source's line).
    m_transponderState = new QLabel;
    m_transponderState->setObjectName(QStringLiteral("radioTransponderState"));
    m_transponderState->setWordWrap(true);
    m_transponderState->hide();
    planLayout->addWidget(m_transponderState);

    m_planBox = box(QString(), plan, QStringLiteral("radioPlanBox"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    auto *radioBox = new QWidget;
    auto *radioLayout = new QVBoxLayout(radioBox);
    radioLayout->setContentsMargins(0, 0, 0, 0);
    radioLayout->setSpacing(3);
    radioLayout->addWidget(m_link);
    radioLayout->addWidget(vfos);
    layout->addWidget(box(tr("Radio"), radioBox, QStringLiteral("radioLinkGroup")));
    layout->addWidget(m_planBox);
    // The operator's hand back on the radio at any moment; and off again:
    // through the station's face, as every station window has it.
    auto *hold = new RadioControlButton(m_station->face());
    connect(hold, &RadioControlButton::message, this, &RadioPanel::message);
    connect(radio, &station::DopplerRadio::controlHeldChanged, m_readout, &RadioReadout::refresh);
    auto *during = new QWidget;
    auto *duringLayout = new QVBoxLayout(during);
    duringLayout->setContentsMargins(0, 0, 0, 0);
    duringLayout->setSpacing(4);
    duringLayout->addWidget(new RadioStateLine(m_station->face()));
    duringLayout->addWidget(m_readout);
    // Across the passband, as the radio's dial; beside Stop radio control.
    auto *tuner = new RadioPassbandTuner(radio);
    tuner->tuneWithWheelOver(m_readout->sentLine());
    connect(tuner, &RadioPassbandTuner::tuned, m_readout, &RadioReadout::refresh);
    auto *controls = new QHBoxLayout;
    controls->setSpacing(8);
    controls->addWidget(hold);
    controls->addWidget(tuner, 1);
    duringLayout->addLayout(controls);
    layout->addWidget(box(tr("During the pass"), during, QStringLiteral("radioReadoutGroup")));
    layout->addStretch(1);

    connect(m_apply, &QPushButton::clicked, this, &RadioPanel::apply);
    connect(m_form, &RadioPlanForm::applyAsked, this, &RadioPanel::apply);
    connect(m_form, &RadioPlanForm::noted, this, &RadioPanel::message);
    // The transponders cached beside the element sets: read at once (no
    // network); fetched only when the operator asks (Refresh transponders).
    radio::TransponderSources *transponders = m_station->transponders();
    connect(transponders, &radio::TransponderSources::transpondersChanged, this, &RadioPanel::showTransponders);
    connect(transponders, &radio::TransponderSources::finished, this, [this, transponders] {
        for (const radio::TransponderSourceStatus &s : transponders->status())
            emit message(tr("transponders: %1").arg(radio::describeTransponderSource(s)));
        showRefreshResult();
    });
    if (transponders->urls().isEmpty())
        transponders->setUrls(radio::savedTransponderUrls());
    transponders->loadFromCache();
    // What `slew --update-transponders` saves while the window is open is
    // read as it lands (radio/transponderwatch.h).
    connect(transponders->followSaved(), &radio::TransponderWatch::followed, this, [this](const QString &what) {
        emit message(tr("transponders: %1").arg(what));
        showTransponderState(tr("Transponders: %1.").arg(what), QString());
    });
    connect(m_link, &RadioLinkBox::message, this, &RadioPanel::message);
    connect(vfos, &RadioVfoChoice::message, this, &RadioPanel::message);
    connect(radio, &station::DopplerRadio::logLine, this, &RadioPanel::message);
    // A satellite tracked: its own frequencies, when it has some kept. The
    // runner says a line as it starts (before it has planned a pass, so
    // before the tracker's state moves) and its tracker's state follows it
    // to the end.
    const tracking::PassRunner *runner = m_station->passRunner();
    connect(runner, &tracking::PassRunner::logLine, this, &RadioPanel::onTracking);
    connect(&runner->tracker(), &tracking::Tracker::stateChanged, this, &RadioPanel::onTracking);
    // A runner stopped while it plans says nothing: looked at each second too.
    connect(&m_watch, &QTimer::timeout, this, &RadioPanel::onTracking);
    m_watch.start(1000);
    // Names for the NORAD numbers come with the element sets.
    connect(m_station->elementSets(), &sky::ElementSetSources::setsChanged, this, &RadioPanel::showPlanState);

    // What was applied last is the radio's again, for the satellite it was for.
    if (const std::optional<int> last = lastAppliedRadioPlan()) {
        if (const std::optional<RadioPlanTexts> kept = keptRadioPlan(*last)) {
            m_form->setTexts(*kept);
            if (std::optional<radio::RadioPlan> restored = m_form->readPlan(*last)) {
                m_station->radio()->setPlan(restored);
                m_readout->refresh();
            }
        }
    }
    onTracking();
    showPlanState();
}

int RadioPanel::trackedNorad() const
{
    const tracking::PassRunner *runner = m_station->passRunner();
    if (!runner->isRunning() || runner->target().kind != tracking::TrackTarget::Kind::Satellite)
        return 0;
    return runner->target().elements.catalogueNumber;
}

QString RadioPanel::describeSatellite(int noradId) const
{
    if (noradId == 0)
        return tr("any satellite tracked");
    for (const sky::ElementSet &set : m_station->elementSets()->sets())
        if (set.catalogueNumber == noradId)
            return tr("%1 (NORAD %2)").arg(set.displayName()).arg(noradId);
    return tr("NORAD %1").arg(noradId);
}

void RadioPanel::refreshTransponders()
{
    radio::TransponderSources *transponders = m_station->transponders();
    if (transponders->urls().isEmpty()) {
        // None kept yet: SatNOGS DB's list, kept from now on.
        const QList<QUrl> urls{QUrl(QString::fromLatin1(radio::kSatnogsTransmittersUrl))};
        radio::saveTransponderUrls(urls);
        transponders->setUrls(urls);
    }
    const QString refreshing = tr("refreshing from %n source(s)", nullptr, int(transponders->urls().size()));
    emit message(tr("transponders: %1").arg(refreshing));
    showTransponderState(tr("Transponders: %1…").arg(refreshing), QString());
    transponders->refresh();
}

void RadioPanel::showTransponderSources()
{
    if (!m_sourcesDialog) {
        m_sourcesDialog = new RadioTransponderDialog(m_station->transponders(), this);
        connect(m_sourcesDialog, &RadioTransponderDialog::message, this, &RadioPanel::message);
    }
    m_sourcesDialog->show();
    m_sourcesDialog->raise();
    m_sourcesDialog->activateWindow();
}

void RadioPanel::showRefreshResult()
{
    const QList<radio::TransponderSourceStatus> status = m_station->transponders()->status();
    QStringList failed;
    int count = 0;
    for (const radio::TransponderSourceStatus &s : status) {
        count += s.count;
        if (!s.fetched || !s.error.isEmpty())
            failed << radio::describeTransponderSource(s);
    }
    if (failed.isEmpty()) {
        showTransponderState(tr("Transponders refreshed: %1 from %2.")
                                 .arg(tr("%n transponder(s)", nullptr, count),
                                      tr("%n source(s)", nullptr, int(status.size()))),
                             QString());
    } else {
        showTransponderState(tr("Transponders: %1 of %2 source(s) not refreshed: %3")
                                 .arg(failed.size())
                                 .arg(status.size())
                                 .arg(failed.join(QStringLiteral("; "))),
                             QString::fromLatin1(tone::kWarning));
    }
}

void RadioPanel::showTransponderState(const QString &text, const QString &colour)
{
    m_transponderState->setText(text);
    m_transponderState->setStyleSheet(colour.isEmpty() ? QString() : QStringLiteral("color:%1;").arg(colour));
    m_transponderState->show();
}

void RadioPanel::showTransponders()
{
    const int norad = trackedNorad();
    m_form->setTransponders(norad != 0 ? m_station->transponders()->transponders().forSatellite(norad)
                                       : QList<radio::Transponder>());
}

void RadioPanel::onTracking()
{
    const int norad = trackedNorad();
    if (norad != m_tracked)
        showTransponders();
    if (norad != 0 && norad != m_tracked) {
        m_tracked = norad;
        if (const std::optional<RadioPlanTexts> kept = keptRadioPlan(norad)) {
            m_form->setTexts(*kept);
            if (apply())
                emit message(tr("radio: %1's frequencies, as kept: %2")
                                 .arg(describeSatellite(norad), describePlan(*m_station->radio()->plan())));
        } else if (const std::optional<radio::Transponder> t =
                       m_station->transponders()->transponders().defaultFor(norad)) {
            // Nothing kept for it: its default transponder, filled in for
            // the operator to look at and Apply.
            const QList<radio::Transponder> all = m_station->transponders()->transponders().forSatellite(norad);
            for (int i = 0; i < all.size(); ++i) {
                if (radio::sameTransponder(all[i], *t)) {
                    m_form->pickTransponder(i);
                    break;
                }
            }
        }
    } else if (norad == 0) {
        m_tracked = 0;
    }
    showPlanState();
}

bool RadioPanel::apply()
{
    const int norad = trackedNorad();
    const std::optional<radio::RadioPlan> plan = m_form->readPlan(norad);
    m_refused = !plan;
    if (!plan) {
        showPlanState();
        return false;
    }
    m_station->radio()->setPlan(plan);
    keepRadioPlan(norad, m_form->texts());
    showPlanState();
    m_readout->refresh(); // the radio says nothing when its plan changes
    return true;
}

void RadioPanel::showPlanState()
{
    const int norad = trackedNorad();
    m_planBox->setTitle(tr("Frequencies for %1").arg(describeSatellite(norad)));
    const std::optional<radio::RadioPlan> &plan = m_station->radio()->plan();
    QString text;
    QString colour;
    if (m_refused) {
        text = tr("Not applied: put right what is marked above.");
        colour = QString::fromLatin1(tone::kRefused);
    } else if (!plan) {
        text = tr("Nothing applied: the radio is left alone.");
    } else {
        text = tr("Applied for %1: %2.").arg(describeSatellite(plan->noradId), describePlan(*plan));
        if (plan->noradId != 0 && norad != 0 && plan->noradId != norad) {
            // The radio would not be tuned for this pass (DopplerRadio
            // checks the plan's satellite at AOS): say so before AOS.
            text += tr(" Not for the satellite tracked: Apply to tune it.");
            colour = QString::fromLatin1(tone::kWarning);
        }
    }
    m_planState->setText(text);
    // Asked each second: a style set again would polish the label again.
    const QString style = colour.isEmpty() ? QString() : QStringLiteral("color:%1;").arg(colour);
    if (m_planState->styleSheet() != style)
        m_planState->setStyleSheet(style);
}

} // namespace slew::ui

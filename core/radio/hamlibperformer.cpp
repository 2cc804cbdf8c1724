// SPDX-License-Identifier: GPL-3.0-or-later
#include "hamlibperformer.h"

#include "hamliblibrary.h"

#include <hamlib/rig.h>

#include <cmath>

namespace slew::radio {

HamlibPerformer::HamlibPerformer(HamlibRadioConfig config, QObject *parent)
    : ExchangePerformer(parent), m_config(std::move(config)), m_session(std::make_shared<std::atomic<int>>(0))
{
    prepareHamlib();
}

HamlibPerformer::~HamlibPerformer()
{
    if (!m_worker)
        return;
    // No result reaches this any more, no job of it is run, and the worker
    // frees the radio and ends once Hamlib returns from what it is doing.
    m_worker->disconnect(this);
    ++*m_session;
    m_worker->finishLater();
}

QString HamlibPerformer::reaching() const
{
    return m_config.device.isEmpty() ? tr("opening the %1").arg(m_config.modelName)
                                     : tr("opening the %1 on %2").arg(m_config.modelName, m_config.device);
}

void HamlibPerformer::open(VfoLayout layout)
{
    ++*m_session; // the results of an opening before go unheard
    m_layout = layout;
    if (!m_worker) {
        m_worker = HamlibWorker::start(m_config, m_session);
        connect(m_worker, &HamlibWorker::done, this, &HamlibPerformer::onDone, Qt::QueuedConnection);
    }
    HamlibJob job;
    job.call = HamlibCall::Open;
    post(job);
}

void HamlibPerformer::leaveSession()
{
    ++*m_session;
    if (m_worker)
        m_worker->post(HamlibJob{*m_session, HamlibCall::Close});
}

void HamlibPerformer::post(HamlibJob job)
{
    job.session = *m_session;
    job.serial = ++m_lastSerial;
    m_worker->post(job);
}

QString HamlibPerformer::text(const RadioCommand &command) const
{
    const bool mainSub = m_layout == VfoLayout::MainSub;
    // With Main/Sub each call names its VFO; with split, the transmit path
    // is the split calls'.
    auto call = [&](const char *name, const QString &arguments = {}) {
        QString line = QLatin1String(name);
        if (mainSub)
            line += command.path == RadioPath::Receive ? QStringLiteral(" Sub") : QStringLiteral(" Main");
        if (!arguments.isEmpty())
            line += QLatin1Char(' ') + arguments;
        return line;
    };
    const bool splitVfo = command.path == RadioPath::Transmit && !mainSub;
    using Call = RadioCommand::Call;
    switch (command.call) {
    case Call::ReadFrequency:
        return call(splitVfo ? "get_split_freq" : "get_freq");
    case Call::SetFrequency:
        return call(splitVfo ? "set_split_freq" : "set_freq", commandHzText(command.hz));
    case Call::SetMode:
        return call(splitVfo ? "set_split_mode" : "set_mode",
                    QStringLiteral("%1 %2").arg(command.mode).arg(command.passbandHz));
    case Call::SetSplit:
        return command.on ? QStringLiteral("set_split_vfo 1 VFOB") : QStringLiteral("set_split_vfo 0 VFOA");
    case Call::ReadSplit:
        return QStringLiteral("get_split_vfo");
    case Call::ReadStep:
        return call("get_ts");
    }
    Q_UNREACHABLE();
}

QString HamlibPerformer::refusal(const RadioCommand &command) const
{
    if (command.call != RadioCommand::Call::SetMode
        || rig_parse_mode(command.mode.toLatin1().constData()) != RIG_MODE_NONE)
        return {};
    return tr("Hamlib knows no mode '%1' (its names: USB, LSB, CW, FM, AM, PKTUSB, ...; capitals)").arg(command.mode);
}

HamlibJob HamlibPerformer::jobFor(const RadioCommand &command) const
{
    const bool mainSub = m_layout == VfoLayout::MainSub;
    const bool receive = command.path == RadioPath::Receive;
    HamlibJob job;
    job.vfo = mainSub ? (receive ? HamlibVfo::Sub : HamlibVfo::Main) : HamlibVfo::Current;
    // The transmit path with split is the split calls' (they name RIG_VFO_TX).
    const bool splitVfo = !receive && !mainSub;
    using Call = RadioCommand::Call;
    switch (command.call) {
    case Call::ReadFrequency:
        job.call = splitVfo ? HamlibCall::GetSplitFreq : HamlibCall::GetFreq;
        break;
    case Call::SetFrequency:
        job.call = splitVfo ? HamlibCall::SetSplitFreq : HamlibCall::SetFreq;
        job.hz = double(std::llround(command.hz)); // whole hertz, what every radio takes
        break;
    case Call::SetMode:
        job.call = splitVfo ? HamlibCall::SetSplitMode : HamlibCall::SetMode;
        job.mode = quint64(rig_parse_mode(command.mode.toLatin1().constData()));
        job.passbandHz = command.passbandHz;
        break;
    case Call::SetSplit:
        job.call = command.on ? HamlibCall::SplitOn : HamlibCall::SplitOff;
        break;
    case Call::ReadSplit:
        job.call = HamlibCall::GetSplit;
        break;
    case Call::ReadStep:
        job.call = HamlibCall::GetStep;
        break;
    }
    return job;
}

void HamlibPerformer::perform(const RadioCommand &command)
{
    post(jobFor(command));
}

void HamlibPerformer::onDone(const HamlibResult &result)
{
    // A result of a session this performer has left, or of nothing it
    // waits for: only the answer to the job on the wire now is that
    // command's (a read of the transmit frequency taken for the receive
    // one's answer would be followed as a turn of the operator's dial).
    if (result.session != *m_session || result.serial != m_lastSerial)
        return;
    const bool failed = result.code != RIG_OK;
    if (result.call == HamlibCall::Open) {
        if (!failed) {
            emit opened();
            return;
        }
        const QString where = m_config.device.isEmpty() ? tr("the %1").arg(m_config.modelName) : m_config.device;
        QString reason = tr("cannot open %1: %2").arg(where, hamlibErrorWords(result.code));
        if (!result.detail.isEmpty())
            reason += tr(" (%1)").arg(result.detail);
        emit lost(reason);
        return;
    }
    RadioAnswer answer;
    answer.code = result.code;
    if (failed)
        answer.why = tr("failed: %1").arg(hamlibErrorWords(result.code));
    else if (result.call == HamlibCall::GetFreq || result.call == HamlibCall::GetSplitFreq
             || result.call == HamlibCall::GetStep || result.call == HamlibCall::GetSplit)
        answer.value = QString::number(result.value, 'g', 17); // read by the script, as rigctld's text is
    emit answered(answer);
}

} // namespace slew::radio

// SPDX-License-Identifier: GPL-3.0-or-later
#include "hamlibworker.h"

#include "hamliblibrary.h"

#include <QFileInfo>
#include <QThread>

#include <hamlib/rig.h>

#include <mutex>

namespace slew::radio {

namespace {

std::atomic<int> g_liveWorkers{0};

// One Hamlib call at a time in the process (see the header). Held only on
// workers' threads.
std::mutex &hamlibTurn()
{
    static std::mutex turn;
    return turn;
}

vfo_t rigVfo(HamlibVfo vfo)
{
    switch (vfo) {
    case HamlibVfo::Main:
        return RIG_VFO_MAIN;
    case HamlibVfo::Sub:
        return RIG_VFO_SUB;
    case HamlibVfo::Current:
        break;
    }
    return RIG_VFO_CURR;
}

} // namespace

HamlibWorker *HamlibWorker::start(const HamlibRadioConfig &config, std::shared_ptr<const std::atomic<int>> session)
{
    prepareHamlib();
    auto *thread = new QThread;
    thread->setObjectName(QStringLiteral("hamlib %1").arg(config.model));
    auto *worker = new HamlibWorker(config, std::move(session));
    worker->moveToThread(thread);
    // finished() is emitted on the thread itself, which then deletes the
    // worker there; the thread object goes from the main thread's loop.
    connect(thread, &QThread::finished, worker, &QObject::deleteLater);
    connect(thread, &QThread::finished, thread, &QObject::deleteLater);
    ++g_liveWorkers;
    connect(thread, &QObject::destroyed, [] { --g_liveWorkers; });
    thread->start();
    return worker;
}

HamlibWorker::HamlibWorker(const HamlibRadioConfig &config, std::shared_ptr<const std::atomic<int>> session)
    : m_config(config), m_session(std::move(session))
{
    static const int registered = qRegisterMetaType<HamlibResult>();
    Q_UNUSED(registered);
}

HamlibWorker::~HamlibWorker()
{
    // Finish has freed the RIG already; this is for a worker ended otherwise.
    if (m_rig) {
        const std::lock_guard turn(hamlibTurn());
        releaseRig();
    }
}

int HamlibWorker::liveCount()
{
    return g_liveWorkers.load();
}

void HamlibWorker::post(const HamlibJob &job)
{
    QMetaObject::invokeMethod(this, [this, job] { run(job); }, Qt::QueuedConnection);
}

void HamlibWorker::finishLater()
{
    post(HamlibJob{0, HamlibCall::Finish});
}

void HamlibWorker::run(const HamlibJob &job)
{
    if (job.call == HamlibCall::Finish || job.call == HamlibCall::Close) {
        {
            const std::lock_guard turn(hamlibTurn());
            releaseRig();
        }
        if (job.call == HamlibCall::Finish)
            QThread::currentThread()->quit();
        return;
    }

    HamlibResult result;
    result.session = job.session;
    result.serial = job.serial;
    result.call = job.call;
    {
        const std::lock_guard turn(hamlibTurn());
        // Checked after the turn came: another radio's timeouts may have
        // kept this job waiting while its link moved on.
        if (job.session != m_session->load())
            return;
        if (job.call != HamlibCall::Open && !m_rig) {
            result.code = -RIG_EINVAL; // no radio open; the link does not ask this
        } else {
            const vfo_t vfo = rigVfo(job.vfo);
            freq_t hz = 0;
            split_t split = RIG_SPLIT_OFF;
            vfo_t transmitVfo = RIG_VFO_NONE;
            switch (job.call) {
            case HamlibCall::Open:
                result.code = openRig(&result.detail);
                break;
            case HamlibCall::GetFreq:
                result.code = rig_get_freq(m_rig, vfo, &hz);
                result.value = hz;
                break;
            case HamlibCall::SetFreq:
                result.code = rig_set_freq(m_rig, vfo, job.hz);
                break;
            // The split calls name the transmit VFO. Named as the current
            // one, Hamlib 4.5.4's dummy rig sets and reads VFO A, the
            // receive side: a receive reading then shows the transmit
            // frequency, and was followed as a turn of the dial.
            case HamlibCall::SetSplitFreq:
                result.code = rig_set_split_freq(m_rig, RIG_VFO_TX, job.hz);
                break;
            case HamlibCall::GetSplitFreq:
                result.code = rig_get_split_freq(m_rig, RIG_VFO_TX, &hz);
                result.value = hz;
                break;
            case HamlibCall::GetSplit:
                result.code = rig_get_split_vfo(m_rig, RIG_VFO_CURR, &split, &transmitVfo);
                result.value = split == RIG_SPLIT_ON ? 1 : 0;
                break;
            case HamlibCall::SplitOn:
                result.code = rig_set_split_vfo(m_rig, RIG_VFO_CURR, RIG_SPLIT_ON, RIG_VFO_B);
                break;
            case HamlibCall::SplitOff:
                result.code = rig_set_split_vfo(m_rig, RIG_VFO_CURR, RIG_SPLIT_OFF, RIG_VFO_A);
                break;
            case HamlibCall::SetMode:
                result.code = rig_set_mode(m_rig, vfo, rmode_t(job.mode), pbwidth_t(job.passbandHz));
                break;
            case HamlibCall::SetSplitMode:
                result.code = rig_set_split_mode(m_rig, RIG_VFO_TX, rmode_t(job.mode), pbwidth_t(job.passbandHz));
                break;
            case HamlibCall::GetStep:
                result.value = tuningStepHz(job.vfo);
                break;
            case HamlibCall::Close:
            case HamlibCall::Finish:
                break;
            }
        }
    }
    emit done(result);
}

int HamlibWorker::openRig(QString *detail)
{
    releaseRig();
    m_rig = rig_init(rig_model_t(m_config.model));
    if (!m_rig) {
        *detail = tr("Hamlib could not set up model %1").arg(m_config.model);
        return -RIG_EINTERNAL;
    }
    int code = RIG_OK;
    if (!m_config.device.isEmpty())
        code = setting("rig_pathname", m_config.device.toLocal8Bit(), detail);
    if (code == RIG_OK && m_config.baud > 0)
        code = setting("serial_speed", QByteArray::number(m_config.baud), detail);
    if (code == RIG_OK && m_config.civAddress > 0)
        code = setting("civaddr", QByteArray::number(m_config.civAddress), detail);
    if (code == RIG_OK) {
        code = rig_open(m_rig);
        // Readings are of the radio, not of Hamlib's memory of what it was
        // sent: the dial is followed from them (its cache would hide a turn
        // for up to half a second, and hid the fault below).
        if (code == RIG_OK)
            rig_set_cache_timeout_ms(m_rig, HAMLIB_CACHE_ALL, 0);
        // Hamlib says "IO error" for a device that is not there and one
        // the user may not open alike; the file says which.
        if (code != RIG_OK && !m_config.device.isEmpty()) {
            const QFileInfo device(m_config.device);
            if (!device.exists())
                *detail = tr("it does not exist");
            else if (!device.isReadable() || !device.isWritable())
                *detail = tr("no permission to read and write it");
        }
    }
    if (code != RIG_OK) {
        rig_cleanup(m_rig);
        m_rig = nullptr;
    }
    return code;
}

int HamlibWorker::setting(const char *name, const QByteArray &value, QString *detail)
{
    const token_t token = rig_token_lookup(m_rig, name);
    if (token == RIG_CONF_END) {
        *detail = tr("Hamlib has no setting %1 for this model").arg(QString::fromLatin1(name));
        return -RIG_ECONF;
    }
    const int code = rig_set_conf(m_rig, token, value.constData());
    if (code != RIG_OK)
        *detail = tr("Hamlib refused %1=%2").arg(QString::fromLatin1(name), QString::fromLocal8Bit(value));
    return code;
}

double HamlibWorker::tuningStepHz(HamlibVfo vfo)
{
    // The radio's own step where it has one; 0 means none set.
    shortfreq_t step = 0;
    if (rig_get_ts(m_rig, rigVfo(vfo), &step) == RIG_OK && step > 0)
        return double(step);
    // Else the finest step the model lists for the mode it is in.
    rmode_t mode = RIG_MODE_NONE;
    pbwidth_t width = 0;
    if (rig_get_mode(m_rig, rigVfo(vfo), &mode, &width) != RIG_OK || mode == RIG_MODE_NONE)
        return 1.0;
    shortfreq_t finest = 0;
    for (const tuning_step_list &entry : m_rig->caps->tuning_steps) {
        if (RIG_IS_TS_END(entry))
            break;
        // A step of 0 (RIG_TS_ANY) says any step goes: no finest one.
        if ((entry.modes & mode) && entry.ts > 0 && (finest == 0 || entry.ts < finest))
            finest = entry.ts;
    }
    return finest > 0 ? double(finest) : 1.0;
}

void HamlibWorker::releaseRig()
{
    if (!m_rig)
        return;
    rig_close(m_rig);
    rig_cleanup(m_rig);
    m_rig = nullptr;
}

} // namespace slew::radio

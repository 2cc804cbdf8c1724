#include "controllerrotors.h"

#include "model/savedcalibration.h"
#include "transport/sharedline.h"

namespace slew::session {

ControllerRotors::ControllerRotors(RotatorSession *main, QObject *parent) : QObject(parent), m_main(main)
{
    m_main->setLinkMaker([this](const QString &uri) { return makeLink(uri); });
    connect(m_main, &RotatorSession::stateChanged, this, &ControllerRotors::onMainState);
    // The operator's limits and park are the controller's: every rotor keeps them.
    connect(m_main, &RotatorSession::profileChanged, this, [this] {
        for (size_t i = 0; i < m_others.size(); ++i) {
            if (m_others[i])
                m_others[i]->setProfile(profileOf(int(i) + 1));
        }
    });
}

ControllerRotors::~ControllerRotors()
{
    // The main session may outlive us: it goes back to links of its own.
    m_main->setLinkMaker({});
    m_others.clear();
}

transport::LinkResult ControllerRotors::makeLink(const QString &uri)
{
    if (m_main->codec().row().rotorsOnLine <= 1)
        return transport::createLink(uri);
    // A new line (another port or host): the old one's rotors go with it.
    if (!m_line || m_line->uri() != transport::SharedLine::lineUri(uri)) {
        clearOthers();
        m_line = std::make_unique<transport::SharedLine>(uri);
    }
    return m_line->makeLink(uri);
}

QList<RotatorSession *> ControllerRotors::rotors() const
{
    QList<RotatorSession *> all;
    for (int n = 1; n <= int(m_others.size()); ++n)
        all.append(rotor(n));
    return all;
}

RotatorSession *ControllerRotors::rotor(int n) const
{
    if (n < 1 || n > int(m_others.size()))
        return nullptr;
    if (n == m_main->rotor())
        return m_main;
    return m_others[size_t(n - 1)].get();
}

int ControllerRotors::stopOthers(const QString &cause)
{
    int sent = 0;
    for (const auto &other : m_others) {
        if (other && other->isConnected() && other->stop(cause))
            ++sent;
    }
    return sent;
}

void ControllerRotors::onMainState(RotatorSession::State state)
{
    const int count = m_main->codec().row().rotorsOnLine;
    const bool onSharedLine = m_line && m_main->link() && count > 1;
    if (state == RotatorSession::State::Disconnected || (state == RotatorSession::State::Connected && !onSharedLine)) {
        clearOthers();
        return;
    }
    if (state != RotatorSession::State::Connected)
        return; // connecting or reconnecting: the others follow once it is back
    if (int(m_others.size()) != count) {
        clearOthers();
        m_others.resize(size_t(count));
    }
    const int mine = m_main->rotor();
    for (int n = 1; n <= count; ++n) {
        auto &other = m_others[size_t(n - 1)];
        if (n == mine) {
            other.reset();
            continue;
        }
        if (!other) {
            other = std::make_unique<RotatorSession>();
            transport::SharedLine *line = m_line.get();
            other->setLinkMaker([line](const QString &uri) { return line->makeLink(uri); });
        }
        other->setOptions(m_main->options());
        other->setProfile(profileOf(n));
        // The line is open already: the others share it from the first byte.
        if (other->state() == RotatorSession::State::Disconnected)
            other->connectTo(transport::SharedLine::rotorUri(m_line->uri(), n));
    }
    emit rotorsChanged();
}

model::RotatorProfile ControllerRotors::profileOf(int n) const
{
    // The controller's profile, but this rotor's own calibration: each
    // rotor turns its own antenna, whose mechanical zero is its own. One
    // never aligned on the sun or the moon has none.
    model::RotatorProfile profile = m_main->profile();
    const model::CalibrationOffsets offsets =
        m_line ? model::savedCalibration(transport::SharedLine::rotorUri(m_line->uri(), n)).value_or(model::CalibrationOffsets{})
               : model::CalibrationOffsets{};
    profile.azOffsetDeg = offsets.azDeg;
    profile.elOffsetDeg = offsets.elDeg;
    return profile;
}

void ControllerRotors::clearOthers()
{
    if (m_others.empty())
        return;
    m_others.clear();
    emit rotorsChanged();
}

} // namespace slew::session

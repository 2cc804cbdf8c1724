#include "rotor/configeditor.h"

#include "operatortheme.h"
#include "widgets/filechooser.h"

#include <QScopeGuard>

#include <utility>

#include "input/finitenumber.h"

#include "model/movegate.h"
#include "protocol/dialect.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace slew::ui {

using session::RotatorSession;

namespace {

constexpr int kFirstReadOnly = 9; // CR9 control mode, CR10..13 commanded values
constexpr int kLastKnown = 13;
constexpr double kReadBackTolerance = 0.006; // controllers answer with two decimals

QString registerName(int reg)
{
    static const char *names[] = {"",        "Az P gain",    "Az I gain",    "Az D gain",    "El P gain",
                                  "El I gain", "El D gain",    "Park az (°)",  "Park el (°)",  "Control mode",
                                  "Commanded az", "Commanded el", "Commanded az speed", "Commanded el speed"};
    return reg >= 1 && reg <= kLastKnown ? QObject::tr(names[reg]) : QObject::tr("Register %1").arg(reg);
}

bool sameValue(const QString &a, const QString &b)
{
    const std::optional<double> x = input::finiteNumber(a), y = input::finiteNumber(b);
    if (x && y)
        return std::abs(*x - *y) <= kReadBackTolerance;
    return a.trimmed() == b.trimmed();
}

} // namespace

ConfigEditor::ConfigEditor(RotatorSession *session, QWidget *parent) : QWidget(parent), m_session(session)
{
    setObjectName(QStringLiteral("configEditor"));
    auto *table = new QWidget;
    m_grid = new QGridLayout(table);
    m_grid->setColumnStretch(2, 1);
    int col = 0;
    for (const QString &h : {tr("Reg"), tr("Name"), tr("New value"), tr("Device"), tr("State")}) {
        auto *l = new QLabel(QStringLiteral("<b>%1</b>").arg(h));
        m_grid->addWidget(l, 0, col++);
    }
    for (int reg = 1; reg <= kLastKnown; ++reg)
        rowFor(reg);
    auto *scroll = new QScrollArea;
    scroll->setWidget(table);
    scroll->setWidgetResizable(true);

    auto button = [this](const QString &text, const QString &name) {
        auto *b = new QPushButton(text);
        b->setObjectName(name);
        b->setAutoDefault(false);
        return b;
    };
    QPushButton *apply = button(tr("Apply changes"), QStringLiteral("configApply"));
    QPushButton *read = button(tr("Read device"), QStringLiteral("configRead"));
    QPushButton *readOne = button(tr("Read register"), QStringLiteral("configReadRegister"));
    QPushButton *importButton = button(tr("Import profile…"), QStringLiteral("configImport"));
    QPushButton *exportButton = button(tr("Export profile…"), QStringLiteral("configExport"));
    m_extra = new QSpinBox;
    m_extra->setObjectName(QStringLiteral("configRegister"));
    m_extra->setRange(1, 99);
    m_extra->setValue(14);
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("configMessage"));
    m_message->setWordWrap(true);
    m_noRegisters = new QLabel;
    m_noRegisters->setObjectName(QStringLiteral("configNoRegisters"));
    m_noRegisters->setWordWrap(true);
    m_noRegisters->setVisible(false);
    m_registerControls = {scroll, apply, read, readOne, m_extra};

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(apply);
    buttons->addWidget(read);
    buttons->addSpacing(12);
    buttons->addWidget(m_extra);
    buttons->addWidget(readOne);
    buttons->addStretch(1);
    buttons->addWidget(importButton);
    buttons->addWidget(exportButton);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_noRegisters);
    layout->addWidget(scroll, 1);
    layout->addLayout(buttons);
    layout->addWidget(m_message);

    connect(apply, &QPushButton::clicked, this, &ConfigEditor::apply);
    connect(read, &QPushButton::clicked, this, &ConfigEditor::readAll);
    connect(readOne, &QPushButton::clicked, this, [this] { readRegister(m_extra->value()); });
    connect(importButton, &QPushButton::clicked, this, [this] {
        chooseFile(this, FileChoice::Open, tr("Import profile"), {}, tr("Profiles (*.json)"), [this](const QString &path) {
            QString error;
            if (!importProfile(path, &error))
                say(error, true);
        });
    });
    connect(exportButton, &QPushButton::clicked, this, [this] {
        chooseFile(this, FileChoice::Save, tr("Export profile"), QStringLiteral("rotator.json"), tr("Profiles (*.json)"),
                   [this](const QString &path) {
                       QString error;
                       say(exportProfile(path, &error) ? tr("Profile written to %1.").arg(path) : error,
                           !error.isEmpty());
                   });
    });
    connect(session, &RotatorSession::configValueReceived, this, &ConfigEditor::onValue);
    connect(session, &RotatorSession::requestFailed, this, &ConfigEditor::onRequestFailed);
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State state) {
        if (m_round != Round::None && state != RotatorSession::State::Connected) {
            m_round = Round::None;
            m_awaiting.clear();
            say(tr("The link went down before every register had answered."), true);
        }
    });
    connect(session, &RotatorSession::capabilitiesChanged, this, [this](const session::Capabilities &caps) {
        // A fresh connection: read it when the editor is on screen.
        if (caps.probed && caps.config && isVisible())
            readAll();
        m_readOnShow = !isVisible();
        followCapabilities();
    });
    connect(session, &RotatorSession::profileChanged, this, &ConfigEditor::followCapabilities);
    followCapabilities();
}

void ConfigEditor::followCapabilities()
{
    // Before the probe answers nothing is known, and the editor stays as it is.
    const auto &caps = m_session->capabilities();
    const bool none = caps.probed && !caps.config;
    m_noRegisters->setText(none ? tr("%1 has no configuration registers: there is nothing on the controller to "
                                     "read or write here. Profiles can still be imported and exported.")
                                      .arg(protocol::dialectName(m_session->profile().dialect))
                                : QString());
    m_noRegisters->setVisible(none);
    for (QWidget *w : std::as_const(m_registerControls))
        w->setEnabled(!none);
}

ConfigEditor::Row &ConfigEditor::rowFor(int reg)
{
    auto it = m_rows.find(reg);
    if (it != m_rows.end())
        return *it;
    Row row;
    const int line = m_grid->rowCount();
    row.device = new QLabel(QStringLiteral("—"));
    row.device->setObjectName(QStringLiteral("configDevice%1").arg(reg));
    row.state = new QLabel;
    row.state->setObjectName(QStringLiteral("configState%1").arg(reg));
    m_grid->addWidget(new QLabel(QString::number(reg)), line, 0);
    m_grid->addWidget(new QLabel(registerName(reg)), line, 1);
    if (reg < kFirstReadOnly || reg > kLastKnown) {
        row.edit = new QLineEdit;
        row.edit->setObjectName(QStringLiteral("configValue%1").arg(reg));
        connect(row.edit, &QLineEdit::textEdited, this, [this, reg] { onEdited(reg); });
        m_grid->addWidget(row.edit, line, 2);
    } else {
        m_grid->addWidget(new QLabel(tr("read only")), line, 2);
    }
    m_grid->addWidget(row.device, line, 3);
    m_grid->addWidget(row.state, line, 4);
    return *m_rows.insert(reg, row);
}

ConfigEditor::FieldState ConfigEditor::fieldState(int reg) const
{
    return m_rows.contains(reg) ? m_rows[reg].fieldState : FieldState::Unknown;
}

QString ConfigEditor::deviceValue(int reg) const
{
    return m_rows.contains(reg) ? m_rows[reg].deviceText : QString();
}

void ConfigEditor::setState(int reg, FieldState s, const QString &detail)
{
    Row &row = rowFor(reg);
    row.fieldState = s;
    struct Look {
        const char *text;
        const char *colour;
    };
    static const Look looks[] = {{"", ""},           {"", ""},          {"changed", "#f2c03c"},
                                 {"invalid", tone::kRefused}, {"verifying…", "#9aa5b4"}, {"confirmed", "#4cd964"},
                                 {"mismatch", tone::kRefused}, {"no answer", tone::kRefused}};
    const Look &look = looks[int(s)];
    row.state->setText(detail.isEmpty() ? tr(look.text) : QStringLiteral("%1: %2").arg(tr(look.text), detail));
    row.state->setStyleSheet(*look.colour ? QStringLiteral("color:%1;").arg(QLatin1String(look.colour)) : QString());
    if (row.edit) {
        const bool marked = s == FieldState::Changed || s == FieldState::Invalid;
        row.edit->setStyleSheet(marked ? QStringLiteral("QLineEdit{border:2px solid %1;}").arg(QLatin1String(look.colour))
                                       : QString());
    }
}

QString ConfigEditor::validate(int reg, const QString &text) const
{
    const std::optional<double> number = input::finiteNumber(text);
    if (!number)
        return tr("not a number");
    const double v = *number;
    if (reg >= 1 && reg <= 6 && v < 0)
        return tr("gains are not negative");
    // The gate the session will ask when the value is written.
    if (reg == 7)
        return m_session->previewParkRegister(7, v).refusal;
    if (reg == 8)
        return m_session->previewParkRegister(8, v).refusal;
    return {};
}

void ConfigEditor::onEdited(int reg)
{
    Row &row = rowFor(reg);
    const QString text = row.edit->text();
    if (text.trimmed().isEmpty() || (!row.deviceText.isEmpty() && sameValue(text, row.deviceText))) {
        setState(reg, row.deviceText.isEmpty() ? FieldState::Unknown : FieldState::Same);
        return;
    }
    const QString error = validate(reg, text);
    setState(reg, error.isEmpty() ? FieldState::Changed : FieldState::Invalid, error);
}

void ConfigEditor::onValue(int reg, const QString &text)
{
    // Whatever the row makes of it, the round waits for one register less.
    const auto roundEnds = qScopeGuard([this, reg] {
        if (m_awaiting.remove(reg))
            sayWhenRoundEnds();
    });
    Row &row = rowFor(reg);
    row.deviceText = text.trimmed();
    row.device->setText(row.deviceText);
    if (row.fieldState == FieldState::Verifying) {
        const bool same = sameValue(row.written, row.deviceText);
        if (same && row.edit)
            row.edit->setText(row.deviceText);
        setState(reg, same ? FieldState::Confirmed : FieldState::Mismatched,
                 same ? QString() : tr("device has %1").arg(row.deviceText));
        row.written.clear();
        return;
    }
    if (!row.edit || row.fieldState == FieldState::Changed || row.fieldState == FieldState::Invalid)
        return; // keep the operator's edit
    if (row.fieldState == FieldState::Unknown || row.fieldState == FieldState::Same)
        row.edit->setText(row.deviceText);
    if (row.fieldState == FieldState::Unknown)
        setState(reg, FieldState::Same);
}

void ConfigEditor::onRequestFailed(const QString &request, const QString &reason)
{
    static const QRegularExpression configRead(QStringLiteral("^CR\\s*(\\d+)$"));
    const auto match = configRead.match(request);
    if (!match.hasMatch())
        return;
    const int reg = match.captured(1).toInt();
    if (m_rows.contains(reg) && m_rows[reg].fieldState == FieldState::Verifying)
        setState(reg, FieldState::Failed, reason);
    if (m_awaiting.remove(reg)) {
        m_unanswered << registerName(reg);
        sayWhenRoundEnds();
    }
}

void ConfigEditor::startRound(Round round, const QSet<int> &registers)
{
    m_round = round;
    m_awaiting = registers;
    m_unanswered.clear();
    m_roundRegisters = registers;
}

void ConfigEditor::sayWhenRoundEnds()
{
    if (m_round == Round::None || !m_awaiting.isEmpty())
        return;
    const Round round = std::exchange(m_round, Round::None);
    if (round == Round::Reading) {
        say(m_unanswered.isEmpty() ? tr("Read %1 registers.").arg(m_roundRegisters.size())
                                   : tr("Read %1 of %2 registers; no answer for %3.")
                                         .arg(m_roundRegisters.size() - m_unanswered.size())
                                         .arg(m_roundRegisters.size())
                                         .arg(m_unanswered.join(QStringLiteral(", "))),
            !m_unanswered.isEmpty());
        return;
    }
    QStringList disagree;
    for (int reg : std::as_const(m_roundRegisters))
        if (fieldState(reg) != FieldState::Confirmed)
            disagree << registerName(reg);
    disagree.sort();
    say(disagree.isEmpty() ? tr("Wrote %1 register(s); each reads back as written.").arg(m_roundRegisters.size())
                           : tr("Wrote %1 register(s); not confirmed: %2.")
                                 .arg(m_roundRegisters.size())
                                 .arg(disagree.join(QStringLiteral(", "))),
        !disagree.isEmpty());
}

void ConfigEditor::readAll()
{
    if (!m_session->isConnected()) {
        say(tr("Not connected."), true);
        return;
    }
    if (const auto &caps = m_session->capabilities(); caps.probed && !caps.config) {
        say(m_noRegisters->text(), false);
        return;
    }
    QSet<int> asked;
    for (int reg : m_rows.keys()) {
        if ((reg < 10 || reg > 11) && m_session->readConfig(reg)) // CR10/CR11 are polled anyway
            asked << reg;
    }
    // The line says so when the last of them has answered (or not).
    startRound(Round::Reading, asked);
    say(tr("Reading %1 registers…").arg(asked.size()), false);
}

void ConfigEditor::readRegister(int reg)
{
    rowFor(reg);
    if (m_session->readConfig(reg))
        say(tr("Reading register %1…").arg(reg), false);
}

int ConfigEditor::apply()
{
    QStringList problems;
    QList<int> toWrite;
    for (auto it = m_rows.begin(); it != m_rows.end(); ++it) {
        if (it->fieldState == FieldState::Invalid)
            problems << tr("%1: %2").arg(registerName(it.key()), it->state->text());
        else if (it->fieldState == FieldState::Changed)
            toWrite << it.key();
    }
    if (!problems.isEmpty()) {
        say(tr("Nothing was written. Fix first: %1").arg(problems.join(QStringLiteral("; "))), true);
        return 0;
    }
    if (toWrite.isEmpty()) {
        say(tr("Nothing changed."), false);
        return 0;
    }
    int written = 0;
    QSet<int> readingBack;
    for (int reg : toWrite) {
        Row &row = m_rows[reg];
        const QString value = row.edit->text().trimmed();
        if (const session::CommandResult sent = m_session->writeConfig(reg, value); !sent) {
            setState(reg, FieldState::Failed, tr("refused: %1").arg(sent.refusal));
            continue;
        }
        row.written = value;
        setState(reg, FieldState::Verifying);
        if (m_session->readConfig(reg))
            readingBack << reg;
        ++written;
    }
    startRound(Round::WritingBack, readingBack);
    say(tr("Wrote %1 register(s); reading them back…").arg(written), written == 0);
    return written;
}

void ConfigEditor::say(const QString &text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? refusedText() : QString());
}

void ConfigEditor::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_readOnShow && m_session->isConnected() && m_session->capabilities().config) {
        m_readOnShow = false;
        readAll();
    }
}

} // namespace slew::ui

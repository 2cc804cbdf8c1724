#include "rotor/presetpanel.h"

#include "operatortheme.h"
#include "operatoractions.h"

#include <QGridLayout>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>

namespace slew::ui {

namespace {
const char *kSettingsKey = "presets/list";
}

PresetPanel::PresetPanel(face::StationFace *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("presetPanel"));
    m_list = new QListWidget;
    m_list->setObjectName(QStringLiteral("presetList"));
    m_list->setToolTip(tr("Click a preset, or press Alt and its number, to go there"));
    m_list->setMinimumHeight(48); // two rows; it scrolls, and takes more when there is room
    m_name = new QLineEdit;
    m_name->setObjectName(QStringLiteral("presetName"));
    m_name->setPlaceholderText(tr("name"));
    m_store = new QPushButton(tr("Store current"));
    m_store->setObjectName(QStringLiteral("presetStore"));
    m_remove = new QPushButton(tr("Remove"));
    m_remove->setObjectName(QStringLiteral("presetRemove"));
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("presetMessage"));
    m_message->setWordWrap(true);
    for (QPushButton *b : {m_store, m_remove})
        b->setAutoDefault(false);

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(m_list, 0, 0, 1, 3);
    grid->addWidget(m_name, 1, 0);
    grid->addWidget(m_store, 1, 1);
    grid->addWidget(m_remove, 1, 2);
    grid->addWidget(m_message, 2, 0, 1, 3);

    connect(m_list, &QListWidget::itemClicked, this, [this](QListWidgetItem *item) { recall(m_list->row(item)); });
    connect(m_store, &QPushButton::clicked, this, [this] { storeCurrent(m_name->text()); });
    connect(m_name, &QLineEdit::returnPressed, this, [this] { storeCurrent(m_name->text()); });
    connect(m_remove, &QPushButton::clicked, this, &PresetPanel::removeSelected);
    connect(station, &face::StationFace::answered, this, [this](const QString &id, const face::Outcome &outcome) {
        if (id != m_awaiting)
            return;
        m_awaiting.clear();
        if (outcome.isRefused()) {
            m_going = false;
            say(outcome.reason(), true);
        }
    });

    const QJsonDocument doc = QJsonDocument::fromJson(QSettings().value(QLatin1String(kSettingsKey)).toByteArray());
    QString error;
    if (auto loaded = model::PresetList::fromJson(doc.array(), &error))
        m_presets = *loaded;
    else
        say(tr("Saved presets could not be read: %1").arg(error), true);
    refresh();
}

void PresetPanel::refresh()
{
    m_list->clear();
    const auto &list = m_presets.presets();
    for (int i = 0; i < list.size(); ++i) {
        const auto &p = list[i];
        // The key that recalls it (KeyboardControl): Alt+1..9.
        m_list->addItem(QStringLiteral("%1   %2   %3° / %4°")
                            .arg(i < 9 ? tr("Alt+%1").arg(i + 1) : QString::number(i + 1))
                            .arg(p.name)
                            .arg(p.azimuth, 0, 'f', 1)
                            .arg(p.elevation, 0, 'f', 1));
    }
}

void PresetPanel::save() const
{
    QSettings().setValue(QLatin1String(kSettingsKey), QJsonDocument(m_presets.toJson()).toJson(QJsonDocument::Compact));
}

void PresetPanel::moveEnded()
{
    if (m_going)
        say(QString(), false);
}

void PresetPanel::say(const QString &text, bool error)
{
    m_going = false;
    m_message->setText(text);
    m_message->setStyleSheet(error ? refusedText() : QString());
}

bool PresetPanel::recall(int index)
{
    const model::Preset *p = m_presets.at(index);
    if (!p) {
        say(tr("There is no preset %1.").arg(index + 1), true);
        return false;
    }
    const face::Outcome sent = m_station->gotoPosition(p->azimuth, p->elevation);
    if (sent.isRefused()) {
        say(tr("Preset '%1' was not sent: %2").arg(p->name, sent.reason()), true);
        return false;
    }
    m_awaiting = sent.id();
    say(tr("Going to '%1'.").arg(p->name), false);
    m_going = true;
    // Where it goes: the station's target once it has one, else the preset.
    const std::optional<face::StationState> state = m_station->state();
    const QPointF target = sent.isDone() && state && state->target ? *state->target : QPointF(p->azimuth, p->elevation);
    emit moveSent(tr("preset '%1' (%2)").arg(p->name, describePosition(target)), target);
    return true;
}

bool PresetPanel::storeCurrent(const QString &name)
{
    const std::optional<face::StationState> state = m_station->state();
    if (!state || !state->position || state->stale) {
        say(tr("No current position to store."), true);
        return false;
    }
    const QString error =
        m_presets.store(model::Preset{name, state->position->x(), state->position->y()}, state->profileLimits);
    if (!error.isEmpty()) {
        say(error, true);
        return false;
    }
    save();
    refresh();
    m_name->clear();
    say(tr("Stored '%1'.").arg(name.simplified()), false);
    return true;
}

bool PresetPanel::removeSelected()
{
    const int row = m_list->currentRow();
    const QString error = row < 0 ? tr("Select a preset to remove.") : m_presets.remove(row);
    if (!error.isEmpty()) {
        say(error, true);
        return false;
    }
    save();
    refresh();
    say(QString(), false);
    return true;
}

} // namespace slew::ui

// SPDX-License-Identifier: GPL-3.0-or-later
#include "history/historypanel.h"

#include "history/passhistorycsv.h"
#include "history/passpicturedialog.h"
#include "history/passreportpicture.h"
#include "widgets/filechooser.h"

#include "records/passrecordstore.h"
#include "station/station.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace slew::ui {
namespace {

enum Column { Id, Target, Aos, MaxEl, Outcome, Rms, Worst, Commands, Doppler, ColumnCount };

const QString kNone = QStringLiteral("—");

QString degrees(const std::optional<double> &value, int decimals)
{
    return value ? QStringLiteral("%1°").arg(*value, 0, 'f', decimals) : kNone;
}

QString passCount(int n)
{
    return n == 1 ? QObject::tr("1 pass") : QObject::tr("%1 passes").arg(n);
}

QTableWidgetItem *cell(const QString &text, Qt::Alignment align = Qt::AlignRight | Qt::AlignVCenter)
{
    auto *item = new QTableWidgetItem(text);
    item->setTextAlignment(align);
    item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
    return item;
}

// The AOS, and whether it was the real sky's: a rehearsed pass ran by the
// rehearsal clock, so its times are that clock's and its figures are of
// practice, not of a real pass.
QTableWidgetItem *aosCell(const records::PassPlanned &planned)
{
    QString text = planned.aos.isValid() ? planned.aos.toString(QStringLiteral("yyyy-MM-dd HH:mm")) : kNone;
    if (!planned.rehearsal)
        return cell(text, Qt::AlignLeft | Qt::AlignVCenter);
    QTableWidgetItem *item = cell(text + QObject::tr(" · rehearsal"), Qt::AlignLeft | Qt::AlignVCenter);
    item->setToolTip(QObject::tr("Rehearsed: by the rehearsal clock (Sky → Time controller), not the real sky; "
                                 "the times are that clock's."));
    QFont italic = item->font();
    italic.setItalic(true);
    item->setFont(italic);
    return item;
}

} // namespace

HistoryPanel::HistoryPanel(station::Station *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("historyPanel"));
    m_filter = new QLineEdit;
    m_filter->setObjectName(QStringLiteral("historyFilter"));
    m_filter->setPlaceholderText(tr("Filter by target"));
    m_filter->setClearButtonEnabled(true);
    m_picture = new QPushButton(tr("Picture…"));
    m_picture->setObjectName(QStringLiteral("historyPicture"));
    m_export = new QPushButton(tr("Export CSV…"));
    m_export->setObjectName(QStringLiteral("historyExport"));
    for (QPushButton *b : {m_picture, m_export}) {
        b->setAutoDefault(false);
        b->setFocusPolicy(Qt::NoFocus);
    }
    m_table = new QTableWidget(0, ColumnCount);
    m_table->setObjectName(QStringLiteral("historyTable"));
    m_table->setHorizontalHeaderLabels({tr("#"), tr("Target"), tr("AOS (UTC)"), tr("Max el"), tr("Outcome"), tr("RMS"),
                                        tr("Worst"), tr("Cmds"), tr("Doppler")});
    m_table->horizontalHeaderItem(Doppler)->setToolTip(tr("The radio's Doppler error over the pass, RMS"));
    m_table->horizontalHeaderItem(Commands)->setToolTip(tr("Commands sent to the rotator during the pass"));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->setWordWrap(false);
    // The figures keep their width; the target's name takes what is left
    // (cut with "…", whole in its tooltip), so every figure, the Doppler
    // last, stays in view at 1280x720.
    m_table->setTextElideMode(Qt::ElideRight);
    QHeaderView *header = m_table->horizontalHeader();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setSectionResizeMode(Target, QHeaderView::Stretch);
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("historyStatus"));
    m_status->setWordWrap(true);

    auto *controls = new QHBoxLayout;
    controls->addWidget(m_filter, 1);
    controls->addWidget(m_picture);
    controls->addWidget(m_export);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_status);

    // Several changes in a row (a pass ending, the next one dropped) read
    // the file once.
    m_reload = new QTimer(this);
    m_reload->setSingleShot(true);
    m_reload->setInterval(0);
    connect(m_reload, &QTimer::timeout, this, &HistoryPanel::refresh);
    connect(m_station->passRecords(), &records::PassRecordStore::passChanged, m_reload, qOverload<>(&QTimer::start));
    connect(m_filter, &QLineEdit::textChanged, m_reload, qOverload<>(&QTimer::start));
    connect(m_export, &QPushButton::clicked, this, &HistoryPanel::chooseExportFile);
    connect(m_picture, &QPushButton::clicked, this, &HistoryPanel::showSelectedPicture);
    connect(m_table, &QTableWidget::cellDoubleClicked, this, &HistoryPanel::showSelectedPicture);
}

void HistoryPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    refresh();
}

void HistoryPanel::refresh()
{
    const records::PassRecordStore *store = m_station->passRecords();
    m_passes = store->isOpen() ? store->passes(m_filter->text()) : QList<records::PassRecord>{};
    fill();
    QString status;
    if (!store->isOpen())
        status = tr("No pass records are open: passes are not recorded.");
    else
        status = tr("%1%2 in %3%4")
                     .arg(passCount(int(m_passes.size())),
                          m_filter->text().trimmed().isEmpty() ? QString() : tr(" matching the filter"), store->path(),
                          store->canRecord() ? QString() : tr(" (shown only: another Slew records into it)"));
    m_status->setText(status);
    m_status->setToolTip(store->path());
}

void HistoryPanel::fill()
{
    const std::optional<records::PassRecord> was = selected();
    m_table->setRowCount(int(m_passes.size()));
    for (int row = 0; row < m_passes.size(); ++row) {
        const records::PassRecord &r = m_passes[row];
        m_table->setItem(row, Id, cell(QString::number(r.id)));
        QTableWidgetItem *target = cell(r.planned.target, Qt::AlignLeft | Qt::AlignVCenter);
        target->setToolTip(r.planned.target);
        m_table->setItem(row, Target, target);
        m_table->setItem(row, Aos, aosCell(r.planned));
        m_table->setItem(row, MaxEl, cell(degrees(r.planned.maxElevationDeg, 1)));
        QTableWidgetItem *outcome = cell(records::outcomeName(r.outcome), Qt::AlignLeft | Qt::AlignVCenter);
        outcome->setToolTip(r.reason);
        m_table->setItem(row, Outcome, outcome);
        m_table->setItem(row, Rms, cell(degrees(r.figures.rmsDeg, 3)));
        m_table->setItem(row, Worst, cell(degrees(r.figures.worstDeg, 2)));
        m_table->setItem(row, Commands, cell(r.figures.commands ? QString::number(*r.figures.commands) : kNone));
        m_table->setItem(row, Doppler,
                         cell(r.figures.dopplerRmsHz ? QStringLiteral("%1 Hz").arg(*r.figures.dopplerRmsHz, 0, 'f', 1)
                                                     : kNone));
        if (was && was->id == r.id)
            m_table->selectRow(row);
    }
}

std::optional<records::PassRecord> HistoryPanel::selected() const
{
    const QList<QTableWidgetItem *> items = m_table->selectedItems();
    if (items.isEmpty())
        return std::nullopt;
    const int row = items.first()->row();
    return row >= 0 && row < m_passes.size() ? std::optional(m_passes[row]) : std::nullopt;
}

PassPictureDialog *HistoryPanel::showSelectedPicture()
{
    const std::optional<records::PassRecord> pass = selected();
    if (!pass) {
        m_status->setText(tr("Select a pass to see its picture."));
        return nullptr;
    }
    int skipped = 0;
    const QList<records::PassSample> samples = m_station->passRecords()->samples(pass->id, &skipped);
    if (samples.isEmpty()) {
        m_status->setText(pass->outcome == records::Outcome::Dropped
                              ? tr("Pass %1 was dropped: it has no samples to draw.").arg(pass->id)
                              : tr("Pass %1 has no samples left to draw (they are kept %2 days).")
                                    .arg(pass->id)
                                    .arg(m_station->passRecords()->keepDays()));
        return nullptr;
    }
    auto *dialog = new PassPictureDialog(renderPassReport(*pass, samples), QString::number(pass->id), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show(); // not modal: Stop and the rest of the window stay in reach
    emit message(tr("pass %1 (%2): picture shown").arg(pass->id).arg(pass->planned.target));
    return dialog;
}

bool HistoryPanel::exportCsv(const QString &path, QString *error) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    // A write that fails makes commit() fail: one check covers both.
    writePassHistoryCsv(file, m_passes);
    if (!file.commit()) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

void HistoryPanel::chooseExportFile()
{
    chooseFile(this, FileChoice::Save, tr("Export the passes"), QStringLiteral("passes.csv"), tr("CSV files (*.csv)"),
               [this](const QString &path) {
                   QString error;
                   m_status->setText(exportCsv(path, &error)
                                         ? tr("Exported %1 to %2").arg(passCount(int(m_passes.size())), path)
                                         : error);
               });
}

} // namespace slew::ui

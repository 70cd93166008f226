#include "app/AnimationDialog.h"

#include "app/Folders.h"
#include "app/SceneFrames.h"
#include "render/Animation.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>

#include <array>

namespace vf::app {
namespace {

struct FormatEntry {
    const char* suffix;
    const char* name;
    bool transparency;
};

constexpr std::array kFormats{
    FormatEntry{"json", "Lottie (JSON)", true},
    FormatEntry{"svg", "Animated SVG (SMIL)", true},
    FormatEntry{"pdf", "PDF, a page a frame", true},
    FormatEntry{"mp4", "MP4 video (H.264, through ffmpeg)", false},
    FormatEntry{"gif", "Animated GIF (through ffmpeg)", true},
};

const FormatEntry* formatOf(const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    for (const FormatEntry& format : kFormats) {
        if (suffix == QLatin1String(format.suffix))
            return &format;
    }
    return nullptr;
}

QDoubleSpinBox* secondsBox(const char* name)
{
    auto* box = new QDoubleSpinBox;
    box->setObjectName(QLatin1String(name));
    box->setRange(0, 1e6);
    box->setDecimals(3);
    box->setSuffix(QStringLiteral(" s"));
    return box;
}

} // namespace

AnimationDialog::AnimationDialog(model::Scene scene, std::optional<model::ProjectDraft> history, QWidget* parent)
    : QDialog(parent), m_scene(std::move(scene)), m_history(std::move(history))
{
    setWindowTitle(tr("Export Animation"));
    m_path = new QLineEdit(QDir(documentsFolder()).filePath(QStringLiteral("animation.json")));
    m_path->setObjectName(QStringLiteral("path"));
    m_path->setMinimumWidth(40 * m_path->fontMetrics().averageCharWidth());
    auto* browse = new QPushButton(tr("Browse…"));
    browse->setObjectName(QStringLiteral("browse"));
    browse->setAutoDefault(false);
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    m_format = new QLabel;
    m_format->setObjectName(QStringLiteral("format"));

    m_source = new QComboBox;
    m_source->setObjectName(QStringLiteral("source"));
    m_source->addItem(tr("The scene file, from its start"));
    m_source->addItem(tr("The history, as it was made"));
    m_note = new QLabel;
    m_note->setObjectName(QStringLiteral("note"));
    m_note->setWordWrap(true);
    m_start = secondsBox("start");
    m_end = secondsBox("end");
    m_fps = new QSpinBox;
    m_fps->setObjectName(QStringLiteral("fps"));
    m_fps->setRange(1, 240);
    m_fps->setValue(30);
    m_width = new QSpinBox;
    m_width->setObjectName(QStringLiteral("width"));
    m_width->setRange(16, 8192);
    m_width->setValue(576);
    m_width->setSuffix(tr(" px"));
    m_width->setToolTip(tr("Pixels of Lottie and video; points of SVG and PDF"));
    m_transparent = new QCheckBox(tr("Transparent background"));
    m_transparent->setObjectName(QStringLiteral("transparent"));

    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setFormat(tr("%v of %m frames"));
    m_result = new QLabel;
    m_result->setObjectName(QStringLiteral("result"));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* buttons = new QDialogButtonBox;
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    m_export->setObjectName(QStringLiteral("export"));
    m_close = buttons->addButton(QDialogButtonBox::Close);
    m_close->setObjectName(QStringLiteral("close"));

    auto* form = new QFormLayout(this);
    form->addRow(tr("Play:"), m_source);
    form->addRow(m_note);
    form->addRow(tr("File:"), pathRow);
    form->addRow(tr("Format:"), m_format);
    form->addRow(tr("From:"), m_start);
    form->addRow(tr("To:"), m_end);
    form->addRow(tr("Frames per second:"), m_fps);
    form->addRow(tr("Width:"), m_width);
    form->addRow(tr("Background:"), m_transparent);
    form->addRow(m_progress);
    form->addRow(m_result);
    form->addRow(buttons);
    m_export->setDefault(true);

    connect(browse, &QPushButton::clicked, this, &AnimationDialog::browse);
    connect(m_path, &QLineEdit::textChanged, this, &AnimationDialog::updateEnabled);
    for (QDoubleSpinBox* box : {m_start, m_end})
        connect(box, &QDoubleSpinBox::valueChanged, this, &AnimationDialog::updateEnabled);
    connect(m_fps, &QSpinBox::valueChanged, this, &AnimationDialog::updateEnabled);
    connect(buttons, &QDialogButtonBox::accepted, this, &AnimationDialog::start);
    connect(buttons, &QDialogButtonBox::rejected, this, &AnimationDialog::reject);
    connect(m_source, &QComboBox::currentIndexChanged, this, &AnimationDialog::sourceChanged);
    sourceChanged();
}

void AnimationDialog::sourceChanged()
{
    double duration = double(m_scene.time.steps) * m_scene.time.dt;
    if (m_source->currentIndex() == 0) {
        m_note->setText(tr("Plays the document's scene from its start, with its timed drops and strokes; "
                           "ink added by hand is not in it."));
    } else {
        if (!m_spans)  // waits for the newest state, which the worker takes between two steps
            m_spans = m_history->replaySpans(&m_unrecorded);
        duration = model::replayDuration(*m_spans, m_scene.time.dt);
        QString note = tr("Plays every step of the history again, as it was made: drops, strokes, combs and "
                          "gathers at the steps they came, %1 s in all.").arg(duration, 0, 'f', 2);
        if (m_unrecorded > 0)
            note += u' ' + tr("%n command(s) read from a project saved by an older version cannot be played again "
                              "and are left out: such projects kept the states, not what was done between them.",
                              nullptr, m_unrecorded);
        m_note->setText(note);
    }
    m_start->setValue(0);
    m_end->setValue(duration > 0 ? duration : 3.0);
    updateEnabled();
}

AnimationDialog::~AnimationDialog()
{
    m_cancel = true;
    if (m_thread.joinable())
        m_thread.join();
}

void AnimationDialog::reject()
{
    if (running())
        m_cancel = true;  // finished() follows once the thread has stopped
    else
        QDialog::reject();
}

void AnimationDialog::browse()
{
    QFileDialog dialog(this, tr("Export animation to"), m_path->text());
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setNameFilter(tr("Animations (*.json *.svg *.pdf *.mp4 *.gif)"));
    if (dialog.exec() == QDialog::Accepted && !dialog.selectedFiles().isEmpty())
        m_path->setText(dialog.selectedFiles().front());
}

void AnimationDialog::updateEnabled()
{
    const FormatEntry* format = formatOf(m_path->text());
    m_format->setText(format ? QString::fromUtf8(format->name)
                             : tr("unknown: the file must end in .json, .svg, .pdf, .mp4 or .gif"));
    const bool idle = !running();
    const qint64 frames = frameCount({m_start->value(), m_end->value(), double(m_fps->value())});
    for (QWidget* input : std::initializer_list<QWidget*>{m_path, m_start, m_end, m_fps, m_width})
        input->setEnabled(idle);
    m_transparent->setEnabled(idle && format && format->transparency);
    const bool nothingToPlay = m_source->currentIndex() == 1 && m_spans && m_spans->empty();
    m_export->setEnabled(idle && format && frames >= 1 && !nothingToPlay);
    m_source->setEnabled(idle && m_history);
    m_close->setText(idle ? tr("Close") : tr("Cancel"));
    if (idle) {
        m_progress->setRange(0, int(std::max<qint64>(1, std::min<qint64>(frames, INT_MAX))));
        m_progress->setValue(0);
    }
}

void AnimationDialog::start()
{
    if (running() || !m_export->isEnabled())
        return;
    const FrameRange range{m_start->value(), m_end->value(), double(m_fps->value())};
    const QString path = m_path->text();
    render::ExportOptions options;
    options.pageWidth = m_width->value();
    options.dpi = 72;  // raster frames: a pixel a point
    options.background = !(m_transparent->isEnabled() && m_transparent->isChecked());
    m_cancel = false;
    m_result->setText(tr("Exporting…"));
    // The thread owns its copies of the scene and the spans (immutable states) and its own
    // simulation; it reaches the dialog only through queued calls, which Qt drops if the dialog is
    // gone.
    std::optional<std::vector<model::ReplaySpan>> spans;
    if (m_source->currentIndex() == 1)
        spans = m_spans;
    m_thread = std::thread([this, scene = m_scene, spans, range, path, options] {
        QString error;
        try {
            std::unique_ptr<model::Player> player;
            if (spans)
                player = std::make_unique<model::HistoryReplay>(scene, *spans);
            else
                player = std::make_unique<model::SceneRunner>(scene);
            SceneFrames frames(*player, range, [this] { return m_cancel.load(); });
            error = render::exportAnimation(frames.animation(), path, options, [this, &frames](int done) {
                QMetaObject::invokeMethod(this, [this, done] { m_progress->setValue(done); }, Qt::QueuedConnection);
                return !m_cancel.load() && frames.limit().isEmpty();
            });
            if (!frames.limit().isEmpty())
                error = tr("%1: %2; nothing written").arg(path, frames.limit());
        } catch (const std::exception& e) {
            error = QString::fromUtf8(e.what());
        }
        QMetaObject::invokeMethod(this, [this, error] { finished(error); }, Qt::QueuedConnection);
    });
    updateEnabled();
}

void AnimationDialog::finished(const QString& error)
{
    m_thread.join();
    const QString path = m_path->text();
    if (error == path + QStringLiteral(": cancelled")) {
        m_result->setText(tr("Cancelled; nothing written."));
    } else if (!error.isEmpty()) {
        m_result->setText(error);
    } else {
        m_written = path;
        m_result->setText(tr("Wrote %1: %2.")
                              .arg(QDir::toNativeSeparators(path), QLocale().formattedDataSize(QFileInfo(path).size())));
    }
    updateEnabled();
    m_progress->setValue(error.isEmpty() ? m_progress->maximum() : 0);
}

} // namespace vf::app

// The main window's file actions: new, open, recover, save (in the background or waiting), Save
// As, the prompt before unsaved work is dropped, and the title that names the document.
#include "app/MainWindow.h"

#include "app/Folders.h"
#include "app/RecentFiles.h"
#include "app/Recovery.h"
#include "model/ProjectFile.h"
#include "model/SceneFile.h"

#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QStatusBar>

namespace vf::app {

namespace {

const QString saveFolderKey = QStringLiteral("files/saveFolder");  // where Save As saved last
// The backend and device last chosen, for new documents.
const QString backendKey = QStringLiteral("simulation/backend");
const QString deviceKey = QStringLiteral("simulation/device");

// A blank marbling tray: what File ▸ New opens.
model::Scene blankScene()
{
    model::Scene scene;
    scene.canvas.background = QColor(0xf4, 0xee, 0xe2);
    model::applyPreset(scene.flow, model::FluidMode::Marbling);
    scene.time.dt = 0.005;
    return scene;
}

} // namespace

void MainWindow::rememberBackend(const model::EngineSettings& settings)
{
    QSettings().setValue(backendKey, settings.backend);
    QSettings().setValue(deviceKey, settings.device);
}

void MainWindow::newDocument()
{
    ++m_opened;
    m_sceneName.clear();
    const QSettings settings;
    m_document.openScene(blankScene(), settings.value(backendKey, QStringLiteral("opencl")).toString(),
                         settings.value(deviceKey, -1).toInt());
    m_canvas->setBackground(m_document.scene().canvas.background);
    m_canvas->fitToWindow();
    updateTitle();
}

bool MainWindow::load(const QString& path)
{
    ++m_opened;
    if (path.endsWith(QLatin1String(".vfproj"), Qt::CaseInsensitive)) {
        const model::ProjectReadResult read = model::readProjectFile(path);
        if (!read.ok()) {
            m_report(tr("Cannot open project"), read.error);
            return false;
        }
        m_document.openProject(read.project, m_document.settings().backend, m_document.settings().device);
        m_sceneName.clear();
        m_document.setFilePath(path);
    } else {
        const model::SceneReadResult read = model::readSceneFile(path);
        if (!read.ok()) {
            m_report(tr("Cannot open scene"), read.error);
            return false;
        }
        // A scene is a starting point, not the document's file: Save asks where to put the project.
        m_document.openScene(read.scene, m_document.settings().backend, m_document.settings().device);
        m_sceneName = QFileInfo(path).completeBaseName();
    }
    m_canvas->setBackground(m_document.scene().canvas.background);
    m_canvas->fitToWindow();
    updateTitle();
    return true;
}

bool MainWindow::openFile(const QString& path)
{
    if (!load(path))
        return false;
    m_recentFiles->add(path);
    return true;
}

bool MainWindow::recover()
{
    if (!load(m_recovery->filePath()))
        return false;
    // Recovered work has no file of its own yet, and is unsaved until the user saves it.
    m_document.setFilePath({});
    m_document.undoStack().resetClean();
    updateTitle();
    return true;
}

bool MainWindow::saveTo(const QString& path)
{
    m_saves.waitForDone();  // an earlier save of an older draft must not land after this one
    const std::uint64_t revision = m_document.revision();
    return saved(path, m_opened, revision, model::writeProjectFile(m_document.draftProject().finish(), path));
}

void MainWindow::saveInBackground(const QString& path)
{
    // The draft is the document now; waiting for its states and writing them run on a pool
    // thread, so the window stays live while a long history is written.
    // One thread for saves, so that they land in the order they were made.
    m_saves.start([this, draft = m_document.draftProject(), path, opened = m_opened, revision = m_document.revision()] {
        const QString error = model::writeProjectFile(draft.finish(), path);
        QMetaObject::invokeMethod(this, [=, this] { saved(path, opened, revision, error); }, Qt::QueuedConnection);
    });
    statusBar()->showMessage(tr("Saving %1…").arg(QFileInfo(path).fileName()));
}

bool MainWindow::saved(const QString& path, int opened, std::uint64_t revision, const QString& error)
{
    if (!error.isEmpty()) {
        m_report(tr("Cannot save"), error);
        return false;
    }
    m_recentFiles->add(path);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 3000);
    if (opened != m_opened)  // another document was opened while this one was written
        return true;
    m_document.setFilePath(path);
    // Clean only if the history has not moved on while it was written.
    if (m_document.revision() == revision) {
        m_document.undoStack().setClean();
        m_recovery->discard();
    }
    return true;
}

bool MainWindow::save(SaveMode mode)
{
    if (m_document.filePath().isEmpty())
        return saveAs(mode);
    if (mode == SaveMode::Wait)
        return saveTo(m_document.filePath());
    saveInBackground(m_document.filePath());
    return true;
}

bool MainWindow::saveAs(SaveMode mode)
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save project"), suggestedProjectPath(),
                                                tr("Vector Fluid projects (*.vfproj)"));
    if (path.isEmpty())
        return false;
    if (!path.endsWith(QLatin1String(".vfproj"), Qt::CaseInsensitive))
        path += QLatin1String(".vfproj");
    QSettings().setValue(saveFolderKey, QFileInfo(path).absolutePath());
    if (mode == SaveMode::Wait)
        return saveTo(path);
    saveInBackground(path);
    return true;
}

void MainWindow::open()
{
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open"), m_recentFiles->folder(),
                                                      tr("Projects and scenes (*.vfproj *.vfscene);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::maybeSave()
{
    if (!m_document.isModified())
        return true;
    switch (m_ask(tr("Unsaved changes"), tr("Save the changes to this document first?"),
                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel)) {
    case QMessageBox::Save:
        return save(SaveMode::Wait);  // what comes next (closing, opening) needs it done
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    m_recovery->discard();
    event->accept();
}

// The project's own path once it has one; else the scene's name (or Untitled) in the folder of
// the last project saved, or in the documents folder.
QString MainWindow::suggestedProjectPath() const
{
    if (!m_document.filePath().isEmpty())
        return m_document.filePath();
    QString folder = QSettings().value(saveFolderKey).toString();
    if (folder.isEmpty() || !QFileInfo(folder).isDir())
        folder = documentsFolder();
    const QString name = m_sceneName.isEmpty() ? tr("Untitled") : m_sceneName;
    return QDir(folder).filePath(name + QStringLiteral(".vfproj"));
}

void MainWindow::updateTitle()
{
    const QString file = m_document.filePath();
    const QString name = !file.isEmpty() ? QFileInfo(file).fileName() : !m_sceneName.isEmpty() ? m_sceneName : tr("Untitled");
    setWindowTitle(QStringLiteral("%1[*] — Vector Fluid").arg(name));
    setWindowModified(m_document.isModified());
}

} // namespace vf::app

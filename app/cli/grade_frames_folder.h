#pragma once
// The folder a grading batch's frames are drawn into (grade_frames.h): private, in the
// temporary folder, removed with the batch. A batch killed with SIGKILL (or by the system
// running out of memory) cannot remove it, and it may hold up to a gigabyte: so each folder
// holds a lock while its batch lives, and every batch first removes the folders whose batch is
// gone.

#include <QLockFile>
#include <QString>
#include <QTemporaryDir>

#include <memory>

namespace lb {

class FramesFolder
{
public:
    // A new folder, "lightbench-frames-XXXXXX" in QDir::tempPath(), locked; not valid when it
    // could not be made or locked.
    FramesFolder();
    ~FramesFolder();
    FramesFolder(const FramesFolder &) = delete;
    FramesFolder &operator=(const FramesFolder &) = delete;

    bool isValid() const;
    QString path() const;
    // Removes it now (a failed preparation's frames go at once, not at the batch's end).
    void remove();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<QLockFile> m_lock; // let go before the folder goes
};

// Removes the frames folders in QDir::tempPath() whose batch has ended without removing
// them (their lock's process is gone, or they have no whole lock and are an hour old); a live
// batch's folder stays, and so does any folder this user did not make private (another
// user's, or one whose permissions were opened: the portable layer cannot tell owners, and
// removes none). Returns how many.
int removeAbandonedFramesFolders();

} // namespace lb

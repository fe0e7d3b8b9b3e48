// Whether a directory lives on a file system whose remote edits inotify never sees.
#pragma once
#include <cstdint>
#include <string>

namespace fx::detail {

// True for NFS, SMB/CIFS, FUSE (sshfs, ...), 9p (WSL2's /mnt/c, VM shared folders) and
// virtiofs (a FUSE file system), VirtualBox shared folders: inotify there reports only edits made through this kernel,
// so an editor on the host or another machine goes unseen. False if unknown or not determinable.
bool is_network_filesystem(const std::string& directory);

// The same decision for a statfs() f_type magic number.
bool is_network_filesystem_type(int64_t f_type);

}  // namespace fx::detail

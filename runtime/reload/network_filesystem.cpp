#include "network_filesystem.h"

#include <linux/magic.h>
#include <sys/vfs.h>

namespace fx::detail {

bool is_network_filesystem_type(int64_t f_type) {
  switch (uint32_t(f_type)) {
    case NFS_SUPER_MAGIC:
    case SMB_SUPER_MAGIC:
    case CIFS_SUPER_MAGIC:
    case SMB2_SUPER_MAGIC:
    case FUSE_SUPER_MAGIC:  // also virtiofs
    case V9FS_MAGIC:
    case 0x786F4256u:  // vboxsf (VirtualBox shared folders); not in linux/magic.h
      return true;
    default: return false;
  }
}

bool is_network_filesystem(const std::string& directory) {
  struct statfs info {};
  if (::statfs(directory.c_str(), &info) != 0) return false;
  return is_network_filesystem_type(int64_t(info.f_type));
}

}  // namespace fx::detail

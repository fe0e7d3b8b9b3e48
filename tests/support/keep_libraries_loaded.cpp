// Sanitizer builds only (FXKIT_SANITIZE; linked into every test and the fxkit CLI):
// dlclose leaves every library mapped.
//
// The Vulkan loader unloads the driver at vkDestroyInstance. An allocation the driver keeps
// for the life of the process (lavapipe's, for one) is then unreachable, and LeakSanitizer,
// which checks at exit, reports it from "<unknown module>": tests/lsan.supp names driver
// libraries, and an unloaded one has no name left to match (whether lavapipe's shows up
// depends on the Mesa version and its shader cache's state). With the library still mapped
// its pointers stay reachable and a real leak keeps its module name. The executable's
// definition interposes libc's for the loader, which calls dlclose through the PLT.
extern "C" int dlclose(void*) { return 0; }

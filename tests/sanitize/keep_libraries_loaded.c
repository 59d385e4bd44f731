/* Linked into the sanitizer build's executables only (PPR_SANITIZE; scripts/sanitize.sh).
 *
 * The Vulkan loader dlclose()s the driver (lavapipe, with LLVM) and the validation layer at
 * vkDestroyInstance. Heap blocks those libraries' globals still point to then look leaked to
 * LeakSanitizer at exit, and their allocation stacks end in "<unknown module>": code no longer mapped,
 * which no library-name suppression can match and no reader can attribute. Keeping every library
 * mapped until the process ends lets LeakSanitizer scan their globals and name their frames.
 *
 * A definition in the executable comes first in the dynamic linker's lookup, so this one is called
 * in place of libc's (and of the sanitizer runtime's interceptor). Unloading is only ever an
 * optimisation: a library that stays loaded is correct, it merely keeps its memory until exit. */
int dlclose(void* handle) {
    (void)handle;
    return 0;
}

/* Under ThreadSanitizer (make SAN=tsan): Mesa (llvmpipe in libOSMesa, or
 * the EGL driver) is not instrumented and synchronises its rasteriser
 * threads with futexes and atomics TSan cannot see, so the pthread calls it
 * makes look like races among themselves. TSan reads these suppressions at
 * start-up: it ignores the interceptors Mesa and LLVM call, and keeps
 * checking every access of libmodesplit and the tool (the PNG writer
 * thread, png_queue.c). The test programs link this file too
 * (TEST_SUPPORT in the Makefile). */
#if defined(__SANITIZE_THREAD__)
const char *__tsan_default_suppressions(void);
__attribute__((visibility("default"))) const char *__tsan_default_suppressions(void)
{
    return "called_from_lib:libOSMesa.so\n"
           "called_from_lib:libgallium\n"
           "called_from_lib:swrast_dri.so\n"
           "called_from_lib:libEGL_mesa.so\n"
           "called_from_lib:libLLVM\n";
}
#else
typedef int ms_tool_tsan_mesa_unused; /* ISO C: no empty translation unit */
#endif

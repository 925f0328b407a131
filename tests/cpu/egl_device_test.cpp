// Opening the EGL device platform depends on what EGL's client extension string names, and
// drivers name it differently: the strings below are the ones Mesa 22 (Debian 12) and
// NVIDIA's 580 driver (through glvnd, on an H200) returned.
#include "gl/context.h"

#include <gtest/gtest.h>

using namespace vct;

TEST(EglDevice, BothDriversClientStringsOfferTheDevicePlatform) {
    const char* mesa =
        "EGL_EXT_device_base EGL_EXT_device_enumeration EGL_EXT_device_query EGL_EXT_platform_base "
        "EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions EGL_KHR_debug EGL_EXT_platform_device "
        "EGL_EXT_platform_wayland EGL_KHR_platform_wayland EGL_EXT_platform_x11 EGL_KHR_platform_x11 "
        "EGL_EXT_platform_xcb EGL_MESA_platform_gbm EGL_KHR_platform_gbm EGL_MESA_platform_surfaceless";
    // NVIDIA names enumeration only through EGL_EXT_device_base.
    const char* nvidia =
        "EGL_EXT_platform_base EGL_EXT_device_base EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions "
        "EGL_KHR_debug EGL_KHR_platform_x11 EGL_EXT_platform_x11 EGL_EXT_platform_device "
        "EGL_MESA_platform_surfaceless EGL_EXT_explicit_device";
    EXPECT_TRUE(eglCanOpenDevices(mesa));
    EXPECT_TRUE(eglCanOpenDevices(nvidia));
}

TEST(EglDevice, MissingEnumerationOrPlatformIsRefused) {
    EXPECT_FALSE(eglCanOpenDevices(nullptr));
    EXPECT_FALSE(eglCanOpenDevices(""));
    EXPECT_FALSE(eglCanOpenDevices("EGL_EXT_platform_device EGL_EXT_device_query"));
    EXPECT_FALSE(eglCanOpenDevices("EGL_EXT_device_base EGL_EXT_platform_base"));
    // A name is matched whole, not as a prefix of a longer one.
    EXPECT_FALSE(eglCanOpenDevices("EGL_EXT_device_base_x EGL_EXT_platform_device"));
    EXPECT_FALSE(eglCanOpenDevices("EGL_EXT_device_enumeration EGL_EXT_platform_devices"));
    EXPECT_TRUE(eglCanOpenDevices("EGL_EXT_device_enumeration EGL_EXT_platform_device"));
}

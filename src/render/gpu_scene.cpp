#include "render/gpu_scene.h"

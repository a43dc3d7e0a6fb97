#include <shadows/ShadowModule.h>

GS_EXPORT_MODULE("shadows", shadows::ShadowModule)

/* The eta, kappa a model reads from an encoded material (encode.h). */
#include "3_encode/encode.h"

fresnel_rgb encoded_eta(const encoded_material *e, model_eta source, int kappa)
{
    switch (source) {
    case ETA_GAUSS: return kappa ? e->kappa_gauss : e->eta_gauss;
    case ETA_POINT: return kappa ? e->kappa_point : e->eta_point;
    default: return kappa ? e->kappa_fit : e->eta_fit;
    }
}

#if FRESNEL_HAS_F16
const fresnel_f16 *encoded_eta_f16(const encoded_material *e, model_eta source, int kappa)
{
    switch (source) {
    case ETA_GAUSS: return kappa ? e->h_kappa_gauss : e->h_eta_gauss;
    case ETA_POINT: return kappa ? e->h_kappa_point : e->h_eta_point;
    default: return kappa ? e->h_kappa_fit : e->h_eta_fit;
    }
}
#endif

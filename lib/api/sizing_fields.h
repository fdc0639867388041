/* sizing_fields.h - a cvm_sizing's domain-dependent fields built from a mesh handle's domain for
 * one refinement or optimisation, and the refusal of metric sources (sizing_fields.c). */
#ifndef CVM_API_SIZING_FIELDS_H
#define CVM_API_SIZING_FIELDS_H

#include "api_internal.h"
#include "sizing/sizing_internal.h"

/* Build the fields the handle asks for from m's current domain (its input
 * points mark the isolated features of the automatic field); *use is the
 * handle to evaluate (sizing itself when it asks for none). On error
 * (CVM_E_NOMEM, recorded on m) nothing is left to free. Pair with
 * cvm__sizing_fields_end(). */
cvm_status cvm__sizing_fields_begin(cvm_mesh *m, const cvm_sizing *sizing, cvm__sizing_fields *F,
                                    const cvm_sizing **use);
void cvm__sizing_fields_end(cvm_mesh *m, cvm__sizing_fields *F);

/* CVM_E_UNSUPPORTED with a message on m naming call when sizing has a metric
 * source (no meshing call of this version uses one, and none may ignore it);
 * else CVM_OK. */
cvm_status cvm__sizing_refuse_metric(cvm_mesh *m, const cvm_sizing *sizing, const char *call);

/* CVM_E_ARGUMENT with a message on m naming call when sizing holds 3D
 * sources (a 2D meshing call cannot read them); else CVM_OK. */
cvm_status cvm__sizing_refuse_3d(cvm_mesh *m, const cvm_sizing *sizing, const char *call);

#endif

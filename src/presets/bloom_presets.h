/* The presets (presets/): each is a file with three hooks, and the table
 * the engine looks them up in (bloom_preset.c). */
#ifndef BLOOM_PRESETS_H
#define BLOOM_PRESETS_H

#include "bloom_graph.h"

/* Preset hooks: defaults, parameter checks, graph construction. build()
 * makes the graph: g->L and the sizes (the common rule's, bg_levels, are
 * set before from g->cfg), the nodes and g->out_node; and returns in *par
 * what its recipe changes of the parameters the engine filled in (knee,
 * intensity, scratch rows) and what lets the engine skip work (dark_cut,
 * views). It never sees the engine. */
typedef struct {
    const char *name;
    void (*defaults)(bloom_config_t *cfg);
    bloom_status_t (*validate)(const bloom_config_t *cfg);
    bloom_status_t (*build)(bg_graph_t *g, bg_params_t *par);
} bloom_preset_ops_t;

extern const bloom_preset_ops_t bloom_preset_unity;
#if BLOOM_USE_GAMEDEV
extern const bloom_preset_ops_t bloom_preset_gamedev;
#endif
#if BLOOM_USE_XNA
extern const bloom_preset_ops_t bloom_preset_xna;
#endif
#if BLOOM_USE_ATTENUATION
extern const bloom_preset_ops_t bloom_preset_attenuation;
#endif
#if BLOOM_USE_ARM
extern const bloom_preset_ops_t bloom_preset_arm;
#endif
#if BLOOM_USE_COD
extern const bloom_preset_ops_t bloom_preset_cod;
#endif
/* The hooks of preset p, or NULL if unknown or compiled out. */
const bloom_preset_ops_t *bloom_preset_ops(bloom_preset_t p);

#endif

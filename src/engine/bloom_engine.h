/* The engine behind the API (engine/): planning a configuration into its
 * preset's graph, sizing and carving the workspace (bloom.c), the
 * scheduler that makes the rows (bloom_sched.c), the row, band and frame
 * calls (bloom_frame.c). It uses the graph, the presets' hooks, the
 * kernels and the pixel formats; nothing below uses it. */
#ifndef BLOOM_ENGINE_H
#define BLOOM_ENGINE_H

#include "bloom_graph.h"
#include "bloom_presets.h"

/* Plan g from cfg (checked): build the preset's graph into `nodes` (room
 * for cap), dry run. BLOOM_E_WORKSPACE if the graph needs more nodes. */
bloom_status_t bloom_plan(bloom_graph_t *g, const bloom_config_t *cfg, bg_node_t *nodes, int cap);
/* Workspace bytes of the engine: the struct, its nodes, the rings; with
 * base NULL (the engine at base otherwise) only count.
 * per_level[k] (if not NULL, zeroed) gets the ring bytes of level k. */
uint64_t bloom_carve(bloom_graph_t *g, uint8_t *base, size_t *per_level);
/* The dry run: ring sizes, source rows, latency. */
void bloom_dry_frame(bloom_graph_t *g);
bloom_status_t bloom_sched_push(bloom_graph_t *g, const void *src_row, const void *aux_row);
bloom_status_t bloom_sched_pull(bloom_graph_t *g, void *dst_row);

#endif

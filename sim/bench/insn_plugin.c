/* A QEMU TCG plugin that counts the guest instructions a user-mode program
 * executes, exactly (issue 21, section 4; sim/bench/targets.py loads it
 * into qemu-aarch64 / qemu-arm with -plugin). Every translated block adds
 * its instruction count to one 64-bit counter, inline in the generated
 * code, each time it runs; at exit the total is written to the file named
 * by the argument out=PATH (stderr without one).
 *
 * Debian ships QEMU with plugin support (qemu-user, not the -static
 * binaries) but not the plugin header, qemu-plugin.h, so the few calls
 * used are declared here by hand, as QEMU 7.2 (plugin API version 1)
 * defines them. A wrong declaration would show as a wrong count, which
 * port/mcu/cost_selftest.sh rules out on programs of known counts. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
typedef struct qemu_info_t qemu_info_t; /* only passed through */
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };

typedef void (*qemu_plugin_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_tb_trans_cb_t cb);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op, void *ptr,
                                              uint64_t imm);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);

/* The loader checks this against its own API version. */
__attribute__((visibility("default"))) int qemu_plugin_version = 1;
__attribute__((visibility("default"))) int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                                               int argc, char **argv);

/* One guest thread (bloom_icount is single-threaded): the inline adds are
 * not atomic, which is exact for one vCPU. */
static uint64_t insns;
static char out_path[4096];

static void on_tb(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &insns,
                                             (uint64_t)qemu_plugin_tb_n_insns(tb));
}

static void at_end(qemu_plugin_id_t id, void *userdata)
{
    (void)id;
    (void)userdata;
    FILE *f = out_path[0] ? fopen(out_path, "w") : stderr;
    if (!f)
        return;
    fprintf(f, "insns %llu\n", (unsigned long long)insns);
    if (f != stderr)
        fclose(f);
}

int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv)
{
    (void)info;
    for (int i = 0; i < argc; i++) {
        if (strncmp(argv[i], "out=", 4) || strlen(argv[i] + 4) >= sizeof out_path) {
            fprintf(stderr, "insn_plugin: unknown or too long argument %s (wants out=PATH)\n", argv[i]);
            return -1;
        }
        strcpy(out_path, argv[i] + 4);
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_tb);
    qemu_plugin_register_atexit_cb(id, at_end, NULL);
    return 0;
}

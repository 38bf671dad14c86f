/* Abaqus thread utilities for user code run by the host: the 100 predefined mutexes (MutexInit, MutexLock,
 * MutexUnlock, referenced by number 1-100) and the SMA arrays (global arrays shared by all threads, thread-local
 * arrays private to each thread; integer and double precision; created, accessed, sized and deleted by an ID the
 * user chooses), as the Abaqus User Subroutines Guide describes them ("Ensuring thread safety", "Allocatable
 * arrays").
 *
 * Fortran binding: the routines a user calls without a header (MutexInit, MutexLock, MutexUnlock) carry the
 * gfortran/flang external names (lower case, trailing underscore). The array functions are reached through the
 * interfaces of the host's SMAAspUserSubroutines.hdr (host/abaqus), which bind to the ldfcz_sma_* names below and
 * make the initial value optional and of any numeric kind, as the C++ declarations of the same functions do.
 * An array's address is returned as an INTEGER(KIND=8), for a Cray POINTER(ptr, array) in the user's code.
 *
 * Misuse that Abaqus reports as an error (a mutex number outside 1-100, an array that was never created, an ID
 * created twice with another size) ends the run with a message naming the routine and the ID: the user's code
 * would otherwise read or write memory it does not own. */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LDFCZ_MUTEXES 100

static pthread_mutex_t user_mutex[LDFCZ_MUTEXES] = {[0 ... LDFCZ_MUTEXES - 1] = PTHREAD_MUTEX_INITIALIZER};

static void fatal(const char *routine, int id, const char *why)
{
    fflush(stdout);
    fprintf(stderr, "ldfcz: ***ERROR: %s(%d): %s; the analysis stops\n", routine, id, why);
    fflush(stderr);
    exit(3);
}

static int mutex_index(const char *routine, const int *id)
{
    if (id == NULL || *id < 1 || *id > LDFCZ_MUTEXES)
        fatal(routine, id ? *id : 0, "Abaqus provides mutexes 1 to 100 only");
    return *id - 1;
}

/* The mutexes are statically initialised, so MutexInit only checks the number (initialising twice, as user
 * code that calls it from every thread does, is harmless). */
void mutexinit_(const int *id) { (void)mutex_index("MutexInit", id); }
void mutexlock_(const int *id) { pthread_mutex_lock(&user_mutex[mutex_index("MutexLock", id)]); }
void mutexunlock_(const int *id) { pthread_mutex_unlock(&user_mutex[mutex_index("MutexUnlock", id)]); }

/* ---- arrays: a singly linked list per kind (integer / double) and scope (global / this thread) ---- */
enum { SMA_INT = 0, SMA_FLOAT = 1 };

typedef struct sma_array {
    int id;
    int length;
    void *data;
    struct sma_array *next;
} sma_array;

static sma_array *global_arrays[2];
static pthread_mutex_t global_lock = PTHREAD_MUTEX_INITIALIZER;
static __thread sma_array *local_arrays[2];

static const size_t elem_size[2] = {sizeof(int), sizeof(double)};

static sma_array *find(sma_array *head, int id)
{
    for (sma_array *a = head; a != NULL; a = a->next)
        if (a->id == id) return a;
    return NULL;
}

static void fill(sma_array *a, int kind, double value)
{
    for (int i = 0; i < a->length; ++i) {
        if (kind == SMA_INT)
            ((int *)a->data)[i] = (int)value;
        else
            ((double *)a->data)[i] = value;
    }
}

/* Creates the array (or returns the existing one of the same ID and length, as a second thread's creation of a
 * global array does in Abaqus' examples). */
static int64_t create(sma_array **head, int kind, const char *routine, int id, int length, double value)
{
    if (length < 0) fatal(routine, id, "negative size");
    sma_array *a = find(*head, id);
    if (a != NULL) {
        if (a->length != length) fatal(routine, id, "an array with this ID exists with another size");
        return (int64_t)(intptr_t)a->data;
    }
    a = malloc(sizeof *a);
    if (a == NULL) fatal(routine, id, "out of memory");
    a->id = id;
    a->length = length;
    a->data = calloc(length > 0 ? (size_t)length : 1u, elem_size[kind]);
    if (a->data == NULL) fatal(routine, id, "out of memory");
    fill(a, kind, value);
    a->next = *head;
    *head = a;
    return (int64_t)(intptr_t)a->data;
}

static sma_array *existing(sma_array *head, const char *routine, int id)
{
    sma_array *a = find(head, id);
    if (a == NULL) fatal(routine, id, "no array with this ID was created");
    return a;
}

static void delete(sma_array **head, const char *routine, int id)
{
    for (sma_array **p = head; *p != NULL; p = &(*p)->next) {
        if ((*p)->id == id) {
            sma_array *a = *p;
            *p = a->next;
            free(a->data);
            free(a);
            return;
        }
    }
    fatal(routine, id, "no array with this ID was created");
}

#define GLOBAL_CALL(expr)                \
    do {                                 \
        pthread_mutex_lock(&global_lock); \
        expr;                            \
        pthread_mutex_unlock(&global_lock); \
    } while (0)

/* Entry points. For each scope (global: SMA..., thread-local: SMALocal...) and kind (Int, Float): Create, Access,
 * Size, Delete under their Fortran external names, plus Create variants without an initial value and with a
 * single-precision one for the header's generic interface. Global lists are locked around creation, lookup and
 * deletion; element access is the user's to protect with a mutex, as in Abaqus. Thread-local lists need no lock. */
#define LOCKED_global(expr) do { pthread_mutex_lock(&global_lock); expr; pthread_mutex_unlock(&global_lock); } while (0)
#define LOCKED_local(expr) do { expr; } while (0)
#define HEAD_global(kind) (&global_arrays[kind])
#define HEAD_local(kind) (&local_arrays[kind])

#define SMA_ROUTINES(scope, fname, cname, kind, ctype)                                                          \
    int64_t fname##create_(const int *id, const int *length, const ctype *value)                              \
    {                                                                                                          \
        int64_t r;                                                                                             \
        LOCKED_##scope(r = create(HEAD_##scope(kind), kind, cname "Create", *id, *length, (double)*value));   \
        return r;                                                                                              \
    }                                                                                                          \
    int64_t ldfcz_##fname##create_zero(const int *id, const int *length)                                      \
    {                                                                                                          \
        int64_t r;                                                                                             \
        LOCKED_##scope(r = create(HEAD_##scope(kind), kind, cname "Create", *id, *length, 0.0));              \
        return r;                                                                                              \
    }                                                                                                          \
    int64_t fname##access_(const int *id)                                                                     \
    {                                                                                                          \
        sma_array *a;                                                                                          \
        LOCKED_##scope(a = existing(*HEAD_##scope(kind), cname "Access", *id));                               \
        return (int64_t)(intptr_t)a->data;                                                                     \
    }                                                                                                          \
    int fname##size_(const int *id)                                                                           \
    {                                                                                                          \
        sma_array *a;                                                                                          \
        LOCKED_##scope(a = existing(*HEAD_##scope(kind), cname "Size", *id));                                 \
        return a->length;                                                                                      \
    }                                                                                                          \
    void fname##delete_(const int *id) { LOCKED_##scope(delete(HEAD_##scope(kind), cname "Delete", *id)); }

SMA_ROUTINES(global, smaintarray, "SMAIntArray", SMA_INT, int)
SMA_ROUTINES(global, smafloatarray, "SMAFloatArray", SMA_FLOAT, double)
SMA_ROUTINES(local, smalocalintarray, "SMALocalIntArray", SMA_INT, int)
SMA_ROUTINES(local, smalocalfloatarray, "SMALocalFloatArray", SMA_FLOAT, double)

/* single-precision initial values of the float arrays (a literal 0.0 in user code) */
int64_t ldfcz_smafloatarraycreate_r4(const int *id, const int *length, const float *value)
{
    int64_t r;
    LOCKED_global(r = create(HEAD_global(SMA_FLOAT), SMA_FLOAT, "SMAFloatArrayCreate", *id, *length, *value));
    return r;
}

int64_t ldfcz_smalocalfloatarraycreate_r4(const int *id, const int *length, const float *value)
{
    return create(HEAD_local(SMA_FLOAT), SMA_FLOAT, "SMALocalFloatArrayCreate", *id, *length, *value);
}

/* One task on a POSIX thread of its own beside the caller (background_task.f90): the host's pipelined
 * factorization (sparse_system) runs there while the main thread goes on with GMRES and the element loop.
 * The handle is the caller's; nothing is kept here. */
#include <pthread.h>
#include <stdlib.h>

typedef void (*ldfcz_task_fn)(void *);

struct ldfcz_task {
    pthread_t thread;
    ldfcz_task_fn fn;
    void *arg;
};

static void *ldfcz_task_main(void *p)
{
    struct ldfcz_task *t = p;
    t->fn(t->arg);
    return NULL;
}

/* Starts fn(arg) on a new thread with a 64 MiB stack (MUMPS and gfortran place work arrays on the stack; the
 * pages are only reserved); returns the handle, or NULL when no thread could be started (the caller then runs
 * the task itself). */
void *ldfcz_task_start(ldfcz_task_fn fn, void *arg)
{
    pthread_attr_t attr;
    struct ldfcz_task *t = malloc(sizeof *t);
    int rc;
    if (t == NULL)
        return NULL;
    t->fn = fn;
    t->arg = arg;
    if (pthread_attr_init(&attr) != 0) {
        free(t);
        return NULL;
    }
    pthread_attr_setstacksize(&attr, (size_t)64 << 20);
    rc = pthread_create(&t->thread, &attr, ldfcz_task_main, t);
    pthread_attr_destroy(&attr);
    if (rc != 0) {
        free(t);
        return NULL;
    }
    return t;
}

/* Waits for the task to end and frees the handle; returns pthread_join's status (0 ok). */
int ldfcz_task_join(void *handle)
{
    struct ldfcz_task *t = handle;
    int rc;
    if (t == NULL)
        return 0;
    rc = pthread_join(t->thread, NULL);
    free(t);
    return rc;
}

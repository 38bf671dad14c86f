/* Standard output of a job as Abaqus arranges it: what user code writes to unit 6 (WRITE(6,...), PRINT *, C's
 * stdout) lands in JOB.dat, while the host's own messages still reach the terminal or the pipe the program was
 * started with. The redirection is done on file descriptor 1, so it holds for every Fortran runtime in the process
 * (a user library compiled by LLVM flang has its own unit 6) and for C code alike. The descriptor the program
 * started with is kept as the console: it is process state by nature, like stdout itself. */
#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

static int console_fd = -1;

static int console(void) { return console_fd >= 0 ? console_fd : 1; }

/* Points descriptor 1 at path (created, or continued when append is nonzero). 0 on success. */
int ldfcz_stdout_to_file(const char *path, int append)
{
    fflush(stdout);
    if (console_fd < 0) console_fd = dup(1);
    if (console_fd < 0) return -1;
    int fd = open(path, O_WRONLY | O_CREAT | (append ? O_APPEND : O_TRUNC), 0644);
    if (fd < 0) return -1;
    int rc = dup2(fd, 1);
    close(fd);
    return rc < 0 ? -1 : 0;
}

/* Writes n bytes of text (and a newline when newline is nonzero) to the console. */
void ldfcz_console_write(const char *text, int n, int newline)
{
    int fd = console();
    while (n > 0) {
        ssize_t w = write(fd, text, (size_t)n);
        if (w <= 0) return;
        text += w;
        n -= (int)w;
    }
    if (newline) {
        ssize_t w = write(fd, "\n", 1);
        (void)w;
    }
}

/* 1 when the console is a terminal. */
int ldfcz_console_is_terminal(void) { return isatty(console()); }

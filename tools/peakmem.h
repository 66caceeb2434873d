/* The process's peak resident memory, for ct-track's summary and ct-bench. */
#ifndef CT_TOOLS_PEAKMEM_H
#define CT_TOOLS_PEAKMEM_H

/* Peak resident memory in KiB from /proc/self/status (VmHWM, which, unlike
 * getrusage, does not count the parent's image before exec), or -1 where
 * there is no /proc. */
long ct_peak_rss_kib(void);

#endif

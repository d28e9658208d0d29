/* table.c (bench, chapter 1): printing the cost/accuracy table and its CSV. See table.h. */
#include "table.h"

#include <math.h>
#include <string.h>

#include "atomic_file.h"

double table_mrays_per_second(const TableRow *row)
{
    return row->seconds > 0.0 ? 1e-6 * (double)ray_counts_total(row->rays) / row->seconds : 0.0;
}

/* A measured value in a fixed-width column, or "-". */
static void print_measure(FILE *out, const char *format, double value)
{
    if (isnan(value))
        fprintf(out, " %10s", "-");
    else
        fprintf(out, format, value);
}

/* The width of the panel and settings columns: at least their usual width, wider when a
 * row's text is longer, so that long names do not push the columns after them out of
 * line. */
static void text_widths(const TableRow *rows, int count, int *panel, int *settings)
{
    *panel = 26;
    *settings = 40;
    for (int i = 0; i < count; i++) {
        int panel_length = (int)strlen(rows[i].panel);
        int settings_length = (int)strlen(rows[i].settings);
        if (panel_length > *panel)
            *panel = panel_length;
        if (settings_length > *settings)
            *settings = settings_length;
    }
}

/* An error measured against a noisy reference: "<ref" when it
 * is within the reference's own noise (the estimate with that noise taken out is not
 * above 0, `within`), which 0 or a negative number would misstate. */
static void print_error(FILE *out, const char *format, double value, int within)
{
    if (within && !isnan(value))
        fprintf(out, " %10s", TABLE_WITHIN_REFERENCE_NOISE);
    else
        print_measure(out, format, value);
}

void table_print(FILE *out, const TableRow *rows, int count)
{
    int panel_width, settings_width;
    text_widths(rows, count, &panel_width, &settings_width);
    fprintf(out,
            "%-*s %-*s %7s %8s %3s %10s %10s %10s %7s %10s %9s %10s %10s %5s %4s %7s %5s\n",
            panel_width, "panel", settings_width, "settings", "spp", "seconds", "thr", "camera",
            "bounce", "shadow", "Mray/s", "rmse", "+-sd", "rel_mse", "efficiency", "ref%",
            "runs", "var", "nan");
    int marked = 0;
    for (int i = 0; i < count; i++) {
        const TableRow *r = &rows[i];
        fprintf(out, "%-*s %-*s %7.1f %8.2f %3d %10llu %10llu %10llu %7.2f", panel_width,
                r->panel, settings_width, r->settings, r->spp, r->seconds, r->threads,
                (unsigned long long)r->rays.camera, (unsigned long long)r->rays.bounce,
                (unsigned long long)r->rays.shadow, table_mrays_per_second(r));
        print_error(out, " %10.5f", r->rmse, r->rmse == 0.0 && r->reference_share > 0.0);
        if (isnan(r->rmse_spread))
            fprintf(out, " %9s", "-");
        else
            fprintf(out, " +-%7.5f", r->rmse_spread);
        print_error(out, " %10.3e", r->rel_mse, !(r->rel_mse > 0.0));
        print_measure(out, " %10.3g", r->efficiency);
        if (isnan(r->reference_share))
            fprintf(out, " %5s", "-");
        else
            fprintf(out, " %4.0f%%", 100.0 * r->reference_share);
        fprintf(out, " %4d %7s %5llu\n", r->runs > 1 ? r->runs : 1,
                r->infinite_variance ? "inf-var" : "finite", r->nonfinite);
        marked |= r->infinite_variance;
    }
    if (marked)
        fprintf(out, "%s\n", TABLE_INFINITE_VARIANCE_NOTE);
}

static void csv_measure(FILE *out, double value)
{
    if (isnan(value))
        fputc(',', out);
    else
        fprintf(out, ",%.9g", value);
}

/* A text field in double quotes, each quote inside doubled (RFC 4180): commas and
 * quotes in a panel name or its settings stay inside their field. */
static void csv_text(FILE *out, const char *text)
{
    fputc('"', out);
    for (; *text; text++) {
        if (*text == '"')
            fputc('"', out);
        fputc(*text, out);
    }
    fputc('"', out);
}

int table_write_csv(const char *path, const TableRow *rows, int count)
{
    AtomicFile file;
    if (atomic_open(&file, path) != 0)
        return -1;
    fprintf(file.file, "panel,settings,spp,seconds,threads,camera_rays,bounce_rays,shadow_rays,"
                       "mrays_per_second,rmse,rel_mse,efficiency,nonfinite,runs,rmse_sd,"
                       "rel_mse_sd,reference_share,variance\n");
    for (int i = 0; i < count; i++) {
        const TableRow *r = &rows[i];
        csv_text(file.file, r->panel);
        fputc(',', file.file);
        csv_text(file.file, r->settings);
        fprintf(file.file, ",%.6g,%.6f,%d,%llu,%llu,%llu,%.6g", r->spp, r->seconds, r->threads,
                (unsigned long long)r->rays.camera, (unsigned long long)r->rays.bounce,
                (unsigned long long)r->rays.shadow, table_mrays_per_second(r));
        csv_measure(file.file, r->rmse);
        csv_measure(file.file, r->rel_mse);
        csv_measure(file.file, r->efficiency);
        fprintf(file.file, ",%llu,%d", r->nonfinite, r->runs > 1 ? r->runs : 1);
        csv_measure(file.file, r->rmse_spread);
        csv_measure(file.file, r->rel_mse_spread);
        csv_measure(file.file, r->reference_share);
        fprintf(file.file, ",%s\n", r->infinite_variance ? "infinite" : "finite");
    }
    return atomic_close(&file, 0);
}

int table_write_numbers_csv(const char *path, const char *header, const double *values,
                            int rows, int columns, const int *decimals)
{
    AtomicFile file;
    if (atomic_open(&file, path) != 0)
        return -1;
    fprintf(file.file, "%s\n", header);
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < columns; c++)
            fprintf(file.file, "%.*f%c", decimals[c], values[r * columns + c],
                    c + 1 < columns ? ',' : '\n');
    return atomic_close(&file, 0);
}

// Colour management through OpenColorIO 2.1's C++ API, behind the C
// interface of colour.h. The project's only C++ file: no exception leaves
// it, every entry point catches and turns them into a message.
#include "colour.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include <sys/stat.h>

namespace OCIO = OCIO_NAMESPACE;

struct ColourDisplay {
    std::string config_path, display, view, working_space;
    OCIO::ConstCPUProcessorRcPtr cpu; // const apply: safe from any thread
    int have_chromaticities;
    float chromaticities[8];
};

namespace {

void set_error(char *err, int errlen, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

void set_error(char *err, int errlen, const char *fmt, ...)
{
    if (err == nullptr || errlen <= 0)
        return;
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(err, static_cast<size_t>(errlen), fmt, ap);
    va_end(ap);
}

// "'a', 'b', 'c'": the names a message offers instead of a wrong one.
template <typename Count, typename Name> std::string name_list(Count count, Name name)
{
    std::string s;
    for (int i = 0; i < count(); i++) {
        const char *n = name(i);
        if (n == nullptr || n[0] == '\0')
            continue;
        if (!s.empty())
            s += ", ";
        s += "'";
        s += n;
        s += "'";
    }
    return s.empty() ? std::string("none") : s;
}

bool has_display(const OCIO::ConstConfigRcPtr &cfg, const char *display)
{
    for (int i = 0; i < cfg->getNumDisplays(); i++)
        if (std::strcmp(cfg->getDisplay(i), display) == 0)
            return true;
    return false;
}

bool has_view(const OCIO::ConstConfigRcPtr &cfg, const char *display, const char *view)
{
    for (int i = 0; i < cfg->getNumViews(display); i++)
        if (std::strcmp(cfg->getView(display, i), view) == 0)
            return true;
    return false;
}

// xy of the working space's unit colours through the cie_xyz_d65_interchange
// role; false when the config has no such role or the numbers make no sense.
bool find_chromaticities(const OCIO::ConstConfigRcPtr &cfg, const char *working, float xy[8])
{
    if (!cfg->hasRole(OCIO::ROLE_INTERCHANGE_DISPLAY))
        return false;
    float rgb[12] = { 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1 };
    OCIO::ConstProcessorRcPtr p = cfg->getProcessor(working, OCIO::ROLE_INTERCHANGE_DISPLAY);
    OCIO::PackedImageDesc desc(rgb, 4, 1, 3);
    p->getDefaultCPUProcessor()->apply(desc);
    for (int i = 0; i < 4; i++) {
        const double X = rgb[3 * i], Y = rgb[3 * i + 1], Z = rgb[3 * i + 2];
        const double sum = X + Y + Z;
        if (!std::isfinite(sum) || !(sum > 1e-9))
            return false;
        xy[2 * i] = static_cast<float>(X / sum);
        xy[2 * i + 1] = static_cast<float>(Y / sum);
    }
    return true;
}

ColourStatus open_display(const ColourRequest *req, ColourDisplay *d, char *err, int errlen)
{
    char buf[4096];
    const char *origin = "";
    const char *path = colour_config_path(req, &origin, buf, static_cast<int>(sizeof buf), err, errlen);
    if (path == nullptr)
        return COLOUR_ERR_CONFIG;
    d->config_path = path;

    // OpenColorIO's own message for a missing file names neither the cause
    // nor where the name came from; and it would wait for ever on a FIFO
    // with no writer: only a regular file is handed to it.
    struct stat st;
    std::FILE *f = nullptr;
    const char *why = nullptr;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        why = std::strerror(EISDIR);
    else if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        why = "not a regular file";
    else if ((f = std::fopen(path, "rb")) == nullptr)
        why = std::strerror(errno);
    if (why != nullptr) {
        set_error(err, errlen, "cannot read colour configuration '%s' (from %s): %s", path, origin, why);
        return COLOUR_ERR_CONFIG;
    }
    std::fclose(f);
    OCIO::ConstConfigRcPtr cfg;
    try {
        cfg = OCIO::Config::CreateFromFile(path);
        cfg->validate();
    } catch (const std::exception &e) {
        set_error(err, errlen, "colour configuration '%s' (from %s) is broken: %s", path, origin, e.what());
        return COLOUR_ERR_CONFIG;
    }

    // The working space: --colorspace (a colour space, alias or role), else
    // the scene_linear role.
    const char *working = req->colorspace;
    if (working == nullptr && !cfg->hasRole(OCIO::ROLE_SCENE_LINEAR)) {
        set_error(err, errlen,
                  "colour configuration '%s' has no scene_linear role: name the working space with --colorspace "
                  "(valid: %s)",
                  path,
                  name_list([&] { return cfg->getNumColorSpaces(); },
                            [&](int i) { return cfg->getColorSpaceNameByIndex(i); })
                      .c_str());
        return COLOUR_ERR_NAME;
    }
    if (working == nullptr)
        working = OCIO::ROLE_SCENE_LINEAR;
    OCIO::ConstColorSpaceRcPtr ws = cfg->getColorSpace(working);
    if (!ws) {
        set_error(err, errlen, "unknown colour space '%s' in colour configuration '%s' (valid: %s, or a role)",
                  working, path,
                  name_list([&] { return cfg->getNumColorSpaces(); },
                            [&](int i) { return cfg->getColorSpaceNameByIndex(i); })
                      .c_str());
        return COLOUR_ERR_NAME;
    }
    d->working_space = ws->getName();

    const char *display = req->display != nullptr ? req->display : cfg->getDefaultDisplay();
    if (display == nullptr || !has_display(cfg, display)) {
        set_error(err, errlen, "unknown display '%s' in colour configuration '%s' (valid: %s)",
                  display != nullptr ? display : "", path,
                  name_list([&] { return cfg->getNumDisplays(); }, [&](int i) { return cfg->getDisplay(i); })
                      .c_str());
        return COLOUR_ERR_NAME;
    }
    d->display = display;
    const char *view = req->view != nullptr ? req->view : cfg->getDefaultView(display);
    if (view == nullptr || !has_view(cfg, display, view)) {
        set_error(err, errlen, "unknown view '%s' for display '%s' in colour configuration '%s' (valid: %s)",
                  view != nullptr ? view : "", display, path,
                  name_list([&] { return cfg->getNumViews(display); },
                            [&](int i) { return cfg->getView(display, i); })
                      .c_str());
        return COLOUR_ERR_NAME;
    }
    d->view = view;

    try {
        OCIO::DisplayViewTransformRcPtr t = OCIO::DisplayViewTransform::Create();
        t->setSrc(d->working_space.c_str());
        t->setDisplay(d->display.c_str());
        t->setView(d->view.c_str());
        d->cpu = cfg->getProcessor(t)->getDefaultCPUProcessor();
    } catch (const std::exception &e) {
        set_error(err, errlen, "colour configuration '%s': cannot build the transform from '%s' to '%s' / '%s': %s",
                  path, d->working_space.c_str(), d->display.c_str(), d->view.c_str(), e.what());
        return COLOUR_ERR_CONFIG;
    }
    try {
        d->have_chromaticities = find_chromaticities(cfg, d->working_space.c_str(), d->chromaticities);
    } catch (const std::exception &) {
        d->have_chromaticities = 0; // the EXR goes untagged; the render does not depend on it
    }
    return COLOUR_OK;
}

} // namespace

extern "C" {

int colour_ocio_available(void)
{
    return 1;
}

const char *colour_ocio_version(void)
{
    // Built once, on first use; C++ makes that initialisation thread-safe.
    static const std::string v = std::string("OpenColorIO ") + OCIO::GetVersion();
    return v.c_str();
}

ColourStatus colour_display_open(const ColourRequest *req, ColourDisplay **out, char *err, int errlen)
{
    *out = nullptr;
    if (err != nullptr && errlen > 0)
        err[0] = '\0';
    ColourDisplay *d = new (std::nothrow) ColourDisplay();
    if (d == nullptr) {
        set_error(err, errlen, "out of memory");
        return COLOUR_ERR_CONFIG;
    }
    ColourStatus st;
    try {
        st = open_display(req, d, err, errlen);
    } catch (const std::exception &e) {
        set_error(err, errlen, "colour configuration: %s", e.what());
        st = COLOUR_ERR_CONFIG;
    } catch (...) {
        set_error(err, errlen, "colour configuration: unknown error in OpenColorIO");
        st = COLOUR_ERR_CONFIG;
    }
    if (st != COLOUR_OK) {
        delete d;
        return st;
    }
    *out = d;
    return COLOUR_OK;
}

void colour_display_free(ColourDisplay *d)
{
    delete d;
}

int colour_display_apply(const ColourDisplay *d, float *rgb, long n, char *err, int errlen)
{
    if (n <= 0)
        return 0;
    try {
        OCIO::PackedImageDesc desc(rgb, n, 1, 3);
        d->cpu->apply(desc);
    } catch (const std::exception &e) {
        set_error(err, errlen, "display transform failed: %s", e.what());
        return -1;
    } catch (...) {
        set_error(err, errlen, "display transform failed");
        return -1;
    }
    return 0;
}

const char *colour_display_config(const ColourDisplay *d)
{
    return d->config_path.c_str();
}

const char *colour_display_name(const ColourDisplay *d)
{
    return d->display.c_str();
}

const char *colour_display_view(const ColourDisplay *d)
{
    return d->view.c_str();
}

const char *colour_display_working_space(const ColourDisplay *d)
{
    return d->working_space.c_str();
}

int colour_display_chromaticities(const ColourDisplay *d, float xy[8])
{
    if (!d->have_chromaticities)
        return -1;
    std::memcpy(xy, d->chromaticities, sizeof d->chromaticities);
    return 0;
}

} // extern "C"

"""pytest setup: USD must find the package's plugInfo.json before pxr is first imported,
so PXR_PLUGINPATH_NAME is set here, from the installed package's folder."""

import os

import lpe

os.environ["PXR_PLUGINPATH_NAME"] = os.pathsep.join(
    p for p in [lpe.plugin_path(), os.environ.get("PXR_PLUGINPATH_NAME")] if p
)

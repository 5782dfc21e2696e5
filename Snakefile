# contactlib workflow: scenes -> influence matrices -> solutions -> checks, energy,
# profiles -> one dataset a scene -> the paper's figures, a key-numbers table and
# an HTML report (`snakemake --report results/report.html`).
#
#   snakemake --cores 2                       everything the config asks for
#   snakemake --cores 2 --configfile my.yaml  with your own scenes (merged)
#   snakemake --cores 2 materials             material pairs (not part of the above)
#   snakemake --cores 2 viscoelastic          viscoelastic cycles against the rate (neither)
#   snakemake --cores 2 coatings              coatings on elastic substrates against a/h (neither)
#   snakemake -n                              what would run
#
# Layout, interface and habits: docs/workflow.md and docs/conventions.md.

from snakemake.utils import min_version

min_version("9.2")


# Snakemake's own message for a YAML syntax error names neither the file nor the line
from contactlib.io import check_yaml
from snakemake.exceptions import WorkflowError

# (a key given twice, which YAML would keep the last of silently, included); the
# --configfile files too, as `contactlib check-config` reads them
for _path in ["config/config.yaml", *map(str, workflow.overwrite_configfiles or ())]:
    try:
        check_yaml(_path)
    except ValueError as _exc:
        raise WorkflowError(f"invalid configuration:\n  {_exc}") from None


configfile: "config/config.yaml"


report: "workflow/report/workflow.rst"


include: "workflow/rules/common.smk"
include: "workflow/rules/influence.smk"
include: "workflow/rules/solve.smk"
include: "workflow/rules/check.smk"
include: "workflow/rules/energy.smk"
include: "workflow/rules/assemble.smk"
include: "workflow/rules/history.smk"
include: "workflow/rules/physical.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/convergence.smk"
include: "workflow/rules/materials.smk"
include: "workflow/rules/viscoelastic.smk"
include: "workflow/rules/layers.smk"
include: "workflow/rules/fretting.smk"
include: "workflow/rules/stresses.smk"
include: "workflow/rules/coatings.smk"


rule all:
    input:
        all_targets(),
    default_target: True


# ends the process as soon as the run is over (cancel_rate_limiter_timer, common.smk)
onsuccess:
    cancel_rate_limiter_timer()


onerror:
    cancel_rate_limiter_timer()

# The `fretting` target: a rigid cylinder pressed to P_max, then cycled tangentially
# between +-Q* (k = 0.3, Q*/kP = 0.1 ... 0.9, three cycles) on nu = 0.5 (beta = 0,
# against Mindlin-Deresiewicz) and nu = 0.3 (beta = 0.286, coupled): one dataset, a
# figure and a table; and the sphere's stick-zone map (below). Not part of `all`: run
# `snakemake --cores 2 fretting`.


rule fretting_study:
    output:
        f"{RESULTS}fretting/fretting.nc",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/fretting/study.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    script:
        "../scripts/fretting_study.py"


rule fretting_figure:
    input:
        rules.fretting_study.output,
    output:
        png=report(
            f"{RESULTS}figures/fretting.png",
            caption="../report/fretting.rst",
            category="Figures",
            labels={"figure": "Fretting: Q-s loops and work per cycle",
                    "file": "fretting.png"},
        ),
        pdf=f"{RESULTS}figures/fretting.pdf",
        csv=f"{RESULTS}tables/fretting.csv",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/fretting/figure.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    script:
        "../scripts/fretting_figure.py"


# The sphere's stick-zone map: a rigid sphere on nu = 0.3 (beta = 0.286) and equal bodies
# with nu = 0 (beta = gamma = 0, Cattaneo-Mindlin exact), P to P_max, then Q/kP 0 -> 0.3
# -> 0.5 -> 0.7 -> 0.9, n = 64, 4 steps a segment (contactlib.fretting_api.stick_map_study,
# about 30 s): the stick zone's radius per direction with its estimate.


rule fretting_stick_map_study:
    output:
        coupled=f"{RESULTS}fretting/stick-map-coupled.nc",
        uncoupled=f"{RESULTS}fretting/stick-map-uncoupled.nc",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/fretting/stick-map-study.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    script:
        "../scripts/fretting_stick_map_study.py"


rule fretting_stick_map:
    input:
        coupled=rules.fretting_stick_map_study.output.coupled,
        uncoupled=rules.fretting_stick_map_study.output.uncoupled,
    output:
        png=report(
            f"{RESULTS}figures/fretting-stick-map.png",
            caption="../report/fretting_stick_map.rst",
            category="Figures",
            labels={"figure": "Fretting: the sphere's stick zone per direction",
                    "file": "fretting-stick-map.png"},
        ),
        pdf=f"{RESULTS}figures/fretting-stick-map.pdf",
        csv=f"{RESULTS}tables/fretting-stick-map.csv",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/fretting/stick-map.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    script:
        "../scripts/fretting_stick_map.py"


rule fretting:
    input:
        rules.fretting_figure.output,
        rules.fretting_stick_map.output,
    default_target: False


# History scenes with a `tangential_path` (fretting scenes): contactlib.fretting
# instead of contactlib.history, one job a scene writing its dataset
# (io.fretting_to_dataset), a table of the path points and a figure (the Q-s curve
# and the stick ratio along the path).


rule fretting_run:
    output:
        dataset=f"{RESULTS}datasets/{{fscene}}.nc",
        table=f"{RESULTS}tables/{{fscene}}.csv",
        png=report(
            f"{RESULTS}figures/{{fscene}}.png",
            caption="../report/fretting_scene.rst",
            category="Fretting scenes",
        ),
        pdf=f"{RESULTS}figures/{{fscene}}.pdf",
    params:
        run=fretting_params,
        version=VERSION,
    log:
        f"{RESULTS}logs/fretting-scenes/{{fscene}}.log",
    benchmark:
        f"{RESULTS}benchmarks/fretting-scenes/{{fscene}}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["history_run"]
    resources:
        mem_mb=1000,
        runtime=10,
    script:
        "../scripts/fretting_run.py"

use super::*;

#[test]
fn defaults_are_the_papers() {
    let c = Campaign::parse("output = \"out\"\nseeds = [1]\n").unwrap();
    assert_eq!((c.seconds, c.population), (30.0, 100));
    assert_eq!(c.terrain, "hilly-1-10");
    assert_eq!(c.validate, ValidationSet::ALL);
    assert_eq!(c.ablation.last_second, 30);
}

#[test]
fn errors_name_the_problem() {
    let unknown = Campaign::parse("output = \"o\"\nseeds = [1]\nseed = 3\n");
    assert!(unknown.unwrap_err().to_string().contains("seed"));
    let shape = "output = \"o\"\nseeds = [1]\n[[evolve]]\nname = \"a\"\nshapes = [\"blob\"]\ncontrollers = [\"mlp\"]\nevals = [10]\n";
    assert!(Campaign::parse(shape)
        .unwrap_err()
        .to_string()
        .contains("blob"));
    let mlp = "output = \"o\"\nseeds = [1]\n[[finetune]]\nname = \"f\"\npairs = [[\"biped-4x3\", \"comb-7x2\"]]\ncontroller = \"mlp\"\nsource_evals = 10\nevals = 10\n";
    assert!(Campaign::parse(mlp)
        .unwrap_err()
        .to_string()
        .contains("attention"));
    let later = "output = \"o\"\nseeds = [1]\n[[evolve]]\nname = \"a\"\nshapes = [\"comb-7x2\"]\ncontrollers = [\"mlp\"]\nevals = [10]\nearlier = [10]\n";
    assert!(Campaign::parse(later)
        .unwrap_err()
        .to_string()
        .contains("earlier budget 10"));
}

#[test]
fn a_budget_below_one_population_is_refused() {
    let group = |population: u32, evals: &str| {
        format!(
            "output = \"o\"\nseeds = [1]\npopulation = {population}\n[[evolve]]\nname = \"a\"\n\
             shapes = [\"comb-7x2\"]\ncontrollers = [\"mlp\"]\nevals = [{evals}]\n"
        )
    };
    assert!(Campaign::parse(&group(100, "100, 30000")).is_ok());
    let error = |text: &str| Campaign::parse(text).unwrap_err().to_string();
    assert_eq!(
        error(&group(100, "30000, 50")),
        "invalid input: group 'a': an evaluation budget of 50 is less than one population of \
         100: the budget must cover at least the initial population"
    );
    assert!(error(&group(0, "10")).contains("population must be at least 1"));
    let finetune = "output = \"o\"\nseeds = [1]\npopulation = 20\n[[finetune]]\nname = \"f\"\n\
                    pairs = [[\"biped-4x3\", \"comb-7x2\"]]\ncontroller = \"attention\"\n\
                    source_evals = 20\nevals = 20\nscratch_evals = 19\n";
    assert!(error(finetune).contains("group 'f': an evaluation budget of 19"));
}

#[test]
fn noninferiority_is_checked() {
    let group = "output = \"o\"\nseeds = [3, 4]\npopulation = 10\n[[evolve]]\nname = \"ni\"\nshapes = [\"comb-7x2\"]\ncontrollers = [\"attention\", \"mlp-comm\"]\nevals = [10]\n";
    let with = |key: &str| Campaign::parse(&format!("{group}noninferiority = {{ {key} }}\n"));
    let ok = with("margin = 0.5, treatment = \"attention\", control = \"mlp-comm\"").unwrap();
    let n = ok.evolve[0].noninferiority.clone().unwrap();
    assert_eq!((n.margin, n.treatment), (0.5, ControllerKind::Attention));
    assert_eq!(n.sets, [ValidationSet::Unseen, ValidationSet::Paper]);
    assert!(n.known_seeds.is_empty());
    let error = |key: &str| with(key).unwrap_err().to_string();
    assert!(
        error("margin = 0.5, treatment = \"mlp\", control = \"mlp-comm\"")
            .contains("mlp is not one of")
    );
    assert!(
        error("margin = -1.0, treatment = \"attention\", control = \"mlp-comm\"")
            .contains("margin")
    );
    assert!(error(
        "margin = 0.5, treatment = \"attention\", control = \"mlp-comm\", known_seeds = [1, 4]"
    )
    .contains("known seed 4"));
    assert!(
        error("margin = 0.5, treatment = \"attention\", control = \"mlp-comm\", alpha = 1")
            .contains("alpha")
    );
}
